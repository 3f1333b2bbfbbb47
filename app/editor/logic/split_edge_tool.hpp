// The Split Edge tool: a click on a network curve splits its edge where the cursor is (at the
// curve parameter picked), by de Casteljau, so the curve does not change; the faces using the
// edge gain a side (a quad becomes a GB pentagon), and the status bar says so. The new vertex is
// selected. A mark shows where a click would split. GUI-free and unit-tested.
#pragma once

#include "app/editor/logic/tool.hpp"

namespace pl {

class SplitEdgeTool final : public ClickTool {
 public:
  SplitEdgeTool() : ClickTool("Split Edge", "K") {}
  // Clicks closer to an end than this (in curve parameter) are refused: the new vertex would
  // all but sit on the old one.
  static constexpr double kEndMargin = 0.02;

  std::string hint() const override;
  void click(ToolContext& ctx, const PointerEvent& e) override;
  void hover(ToolContext& ctx, const PointerEvent& e) override;
  ToolPreview preview(const ToolContext&) const override;
};

// Splits edge e at t for a tool or an action: runs the command, selects the new vertex and
// makes the selection follow the edge's new ends. Returns whether it ran.
bool split_edge_at(Document& doc, Selection& selection,
                   const std::function<void(const std::string&)>& say, int e, double t);

}  // namespace pl
