// The select tool: a click selects what lies under the cursor (a point, a network edge, a face
// or an explicit patch; Shift adds, Ctrl toggles; a click on empty space clears), and a press on
// a point drags the selected points in the view plane (or along a held X / Y / Z axis) as one
// undo step. Handles stay in their vertex's tangent plane (G1 is kept); with Alt held they move
// freely and the plane turns with them, and Alt may be pressed or let go during the drag. A
// press on the knob of a selected vertex's normal handle turns that vertex's tangent plane (one
// undo step however long the drag). A press on a face or edge still orbits when the mouse
// moves, so a surface that fills the view does not stop the designer from turning it.
// GUI-free and unit-tested.
#pragma once

#include "app/editor/logic/plane_handles.hpp"
#include "app/editor/logic/tool.hpp"

namespace pl {

class SelectTool final : public Tool {
 public:
  SelectTool() : Tool("Select", "Q") {}
  std::string hint() const override;
  bool press(ToolContext& ctx, const PointerEvent& e) override;
  void drag(ToolContext& ctx, const PointerEvent& e) override;
  void release(ToolContext& ctx, const PointerEvent& e) override;
  void click(ToolContext& ctx, const PointerEvent& e) override;
  void cancel(ToolContext& ctx) override;
  bool capturing() const override { return captured_; }

 private:
  bool press_knob(ToolContext& ctx, const PointerEvent& e);
  void drag_knob(ToolContext& ctx, const PointerEvent& e);

  bool captured_ = false;  // a press on a point or a knob: until the release
  bool dragging_ = false;  // the document has a drag under way
  HandleMode mode_ = HandleMode::KeepPlane;
  std::vector<PointRef> points_;
  DragMotion motion_;
  ViewRect rect_;
  std::vector<Vec3> start_, last_;
  // Turning a tangent plane by its knob.
  std::optional<PlaneHandle> knob_;
  std::optional<Vec3> knob_normal_;  // the last normal sent
  bool knob_edited_ = false;         // a command of this gesture ran
};

}  // namespace pl
