#include "app/editor/logic/select_tool.hpp"

namespace pl {

std::string SelectTool::hint() const {
  return "click: select (Shift adds, Ctrl toggles); drag a point: move (hold X/Y/Z for an axis; "
         "handles stay in their vertex's tangent plane, Alt moves them freely and turns the "
         "plane); drag a selected vertex's normal knob: turn its tangent plane";
}

bool SelectTool::press_knob(ToolContext& ctx, const PointerEvent& e) {
  const std::vector<PlaneHandle> handles =
      plane_handles(ctx.doc.scene(), ctx.selection, ctx.camera, e.rect, ctx.ui_scale);
  const int k = pick_knob(handles, ctx.camera, e.rect, e.pixel, kKnobPickRadiusPx * ctx.ui_scale);
  if (k < 0) return false;
  // A point at least as near to the cursor as the knob wins (a normal seen end-on puts its knob
  // on its vertex: the press drags the vertex; orbit a little to reach the knob).
  if (e.under && e.under->item && e.under->item->kind == SelectionItem::Kind::Point &&
      point_exists(ctx.doc.scene(), e.under->item->point)) {
    const auto point = project_to_window(ctx.camera, e.rect,
                                         point_position(ctx.doc.scene(), e.under->item->point));
    const auto knob = project_to_window(ctx.camera, e.rect, handles[k].knob);
    if (point && knob && glm::length(*point - e.pixel) <= glm::length(*knob - e.pixel))
      return false;
  }
  knob_ = handles[k];
  knob_normal_.reset();
  knob_edited_ = false;
  motion_ = {knob_->knob, e.pixel};
  rect_ = e.rect;
  captured_ = true;
  ctx.doc.begin_gesture();
  return true;
}

void SelectTool::drag_knob(ToolContext& ctx, const PointerEvent& e) {
  const auto n = dragged_normal(*knob_, motion_, ctx.camera, rect_, e.pixel);
  if (!n || n == knob_normal_ || (!knob_normal_ && *n == knob_->normal)) return;
  knob_normal_ = n;
  // Each move is a command; the gesture makes them one undo step.
  if (run_command(ctx.doc, {}, std::make_shared<SetVertexNormalCommand>(knob_->vertex, *n, true)))
    knob_edited_ = true;
}

bool SelectTool::press(ToolContext& ctx, const PointerEvent& e) {
  if (press_knob(ctx, e)) return true;
  if (!e.under || !e.under->item) return false;
  const SelectionItem item = *e.under->item;
  if (item.kind != SelectionItem::Kind::Point) return false;  // faces and edges: on click
  ctx.selection.click(item, e.select_mode());
  captured_ = true;
  if (!ctx.selection.contains(item)) return true;  // Ctrl took it out: nothing to drag
  points_.clear();
  for (const PointRef& r : ctx.selection.points())
    if (point_exists(ctx.doc.scene(), r)) points_.push_back(r);
  start_.clear();
  for (const PointRef& r : points_) start_.push_back(point_position(ctx.doc.scene(), r));
  last_ = start_;
  motion_ = {point_position(ctx.doc.scene(), item.point), e.pixel};
  rect_ = e.rect;
  mode_ = e.alt ? HandleMode::RotatePlane : HandleMode::KeepPlane;
  ctx.doc.begin_drag(points_, mode_);
  dragging_ = true;
  return true;
}

void SelectTool::drag(ToolContext& ctx, const PointerEvent& e) {
  if (knob_) {
    drag_knob(ctx, e);
    return;
  }
  if (!dragging_) return;
  if (!ctx.doc.dragging()) {  // undone or cancelled meanwhile
    dragging_ = false;
    return;
  }
  // Alt pressed or let go during the drag: the drag goes on in the other mode, from its start
  // (each step starts from there anyway, so nothing drifts).
  const HandleMode mode = e.alt ? HandleMode::RotatePlane : HandleMode::KeepPlane;
  if (mode != mode_) {
    ctx.doc.cancel_drag();
    ctx.doc.begin_drag(points_, mode);
    mode_ = mode;
    last_ = start_;
  }
  const Vec3 d = motion_.offset(ctx.camera, rect_, e.pixel, e.axis);
  std::vector<Vec3> positions = start_;
  for (Vec3& p : positions) p += d;
  // Only real motion is an edit: each drag_to bumps the document's revision.
  if (positions != last_) {
    ctx.doc.drag_to(positions);
    last_ = positions;
  }
}

void SelectTool::release(ToolContext& ctx, const PointerEvent& e) {
  drag(ctx, e);  // the cursor's last position counts even when the release came with it
  if (knob_) {
    ctx.doc.end_gesture();
    if (knob_edited_) ctx.say(ctx.doc.undo_label());
    knob_.reset();
  }
  if (dragging_ && ctx.doc.dragging()) ctx.doc.end_drag();
  dragging_ = captured_ = false;
}

void SelectTool::click(ToolContext& ctx, const PointerEvent& e) {
  if (e.under && e.under->item && !e.alt)
    ctx.selection.click(*e.under->item, e.select_mode());
  else if (!e.shift && !e.ctrl && !e.alt)
    ctx.selection.clear();
}

void SelectTool::cancel(ToolContext& ctx) {
  if (knob_) {
    ctx.doc.end_gesture();
    if (knob_edited_) ctx.doc.undo();  // the plane as it was before the gesture
    knob_.reset();
  }
  if (dragging_ && ctx.doc.dragging()) ctx.doc.cancel_drag();
  dragging_ = captured_ = false;
}

}  // namespace pl
