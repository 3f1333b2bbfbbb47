// The Add Edge tool: click a vertex, then another: a new edge joins them (handles at 1/3 and 2/3
// of the chord, turned into the vertices' tangent planes). The second vertex starts the next
// edge, so a chain of edges is a click per vertex; a click on the last vertex again, on empty
// space or Esc ends the chain. A rubber band runs from the chain's vertex to the cursor.
// GUI-free and unit-tested.
#pragma once

#include "app/editor/logic/tool.hpp"

namespace pl {

class AddEdgeTool final : public ClickTool {
 public:
  AddEdgeTool() : ClickTool("Add Edge", "E") {}
  std::string hint() const override;
  void click(ToolContext& ctx, const PointerEvent& e) override;
  void hover(ToolContext& ctx, const PointerEvent& e) override;
  void cancel(ToolContext&) override { from_ = -1; }
  bool capturing() const override { return from_ >= 0; }
  ToolPreview preview(const ToolContext& ctx) const override;

  int from() const { return from_; }  // the vertex the next edge starts at, -1 if none

 private:
  int from_ = -1;
};

}  // namespace pl
