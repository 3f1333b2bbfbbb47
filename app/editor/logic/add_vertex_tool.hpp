// The Add Vertex tool: a click puts a new network vertex on the surface under the cursor, or
// where the cursor meets the work plane (view-aligned or XY / XZ / YZ through its origin), and
// selects it (Shift adds it to the selection, so a chain of new vertices can be made a face at
// once). A click on an existing vertex selects it (Shift: adds it) rather than adding another
// vertex on top of it. Coordinates typed in the tool's panel go through add_at(). A drag still
// orbits.
// GUI-free and unit-tested.
#pragma once

#include "app/editor/logic/tool.hpp"

namespace pl {

class AddVertexTool final : public ClickTool {
 public:
  AddVertexTool() : ClickTool("Add Vertex", "V") {}
  std::string hint() const override;
  void click(ToolContext& ctx, const PointerEvent& e) override;
  void hover(ToolContext& ctx, const PointerEvent& e) override;
  ToolPreview preview(const ToolContext& ctx) const override;
  bool places_on_work_plane() const override { return true; }

  // Adds a vertex at p and selects it (`add_to_selection`: keeps what was selected). Returns the
  // new vertex, or -1 when refused (a non-finite position).
  int add_at(ToolContext& ctx, const Vec3& p, bool add_to_selection = false);

 private:
  std::string snapped_to_;  // what the hover snapped to last ("" when nothing)
};

}  // namespace pl
