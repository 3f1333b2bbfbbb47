// The select tool: a click selects what lies under the cursor (a point, a network edge, a face
// or an explicit patch; Shift adds, Ctrl toggles; a click on empty space clears), and a press on
// a point drags the selected points in the view plane (or along a held X / Y / Z axis) as one
// undo step. A press on a face or edge still orbits when the mouse moves, so a surface that
// fills the view does not stop the designer from turning it. GUI-free and unit-tested.
#pragma once

#include "app/editor/logic/tool.hpp"

namespace pl {

class SelectTool final : public Tool {
 public:
  std::string name() const override { return "Select"; }
  std::string hint() const override;
  bool press(ToolContext& ctx, const PointerEvent& e) override;
  void drag(ToolContext& ctx, const PointerEvent& e) override;
  void release(ToolContext& ctx, const PointerEvent& e) override;
  void click(ToolContext& ctx, const PointerEvent& e) override;
  void cancel(ToolContext& ctx) override;
  bool capturing() const override { return captured_; }

 private:
  bool captured_ = false;  // a press on a point: until the release
  bool dragging_ = false;  // the document has a drag under way
  DragMotion motion_;
  ViewRect rect_;
  std::vector<Vec3> start_, last_;
};

}  // namespace pl
