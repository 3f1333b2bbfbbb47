// The Make Face tool: click the vertices of a closed chain in order (missing edges between
// consecutive ones are made with the face), or the edges of a closed chain in any order; Enter,
// or a click on the first vertex again, makes the face. Its normal faces the viewer unless
// neighbouring faces decide its direction. A click on a picked edge unpicks it; Esc drops the
// chain. GUI-free and unit-tested.
#pragma once

#include "app/editor/logic/tool.hpp"

namespace pl {

class MakeFaceTool final : public ClickTool {
 public:
  MakeFaceTool() : ClickTool("Make Face", "M") {}
  std::string hint() const override;
  void click(ToolContext& ctx, const PointerEvent& e) override;
  void hover(ToolContext& ctx, const PointerEvent& e) override;
  void cancel(ToolContext&) override;
  bool capturing() const override { return !vertices_.empty() || !edges_.empty(); }
  bool can_finish(const ToolContext& ctx) const override;
  void finish(ToolContext& ctx) override;
  ToolPreview preview(const ToolContext& ctx) const override;

  const std::vector<int>& vertices() const { return vertices_; }
  const std::vector<int>& edges() const { return edges_; }

 private:
  bool valid(const Scene& scene) const;
  std::vector<int> vertices_, edges_;  // one of them is empty
};

// The direction towards the viewer, which a new face's normal follows (MakeFaceCommand's
// `towards`).
Vec3 towards_viewer(const Camera& camera);

}  // namespace pl
