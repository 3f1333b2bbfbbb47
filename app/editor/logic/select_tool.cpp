#include "app/editor/logic/select_tool.hpp"

namespace pl {

std::string SelectTool::hint() const {
  return "click: select (Shift adds, Ctrl toggles); drag a point: move (hold X/Y/Z for an axis)";
}

bool SelectTool::press(ToolContext& ctx, const PointerEvent& e) {
  if (!e.under || !e.under->item || e.alt) return false;
  const SelectionItem item = *e.under->item;
  if (item.kind != SelectionItem::Kind::Point) return false;  // faces and edges: on click
  ctx.selection.click(item, e.select_mode());
  captured_ = true;
  if (!ctx.selection.contains(item)) return true;  // Ctrl took it out: nothing to drag
  std::vector<PointRef> points;
  for (const PointRef& r : ctx.selection.points())
    if (point_exists(ctx.doc.scene(), r)) points.push_back(r);
  start_.clear();
  for (const PointRef& r : points) start_.push_back(point_position(ctx.doc.scene(), r));
  last_ = start_;
  motion_ = {point_position(ctx.doc.scene(), item.point), e.pixel};
  rect_ = e.rect;
  ctx.doc.begin_drag(points);
  dragging_ = true;
  return true;
}

void SelectTool::drag(ToolContext& ctx, const PointerEvent& e) {
  if (!dragging_) return;
  if (!ctx.doc.dragging()) {  // undone or cancelled meanwhile
    dragging_ = false;
    return;
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
  if (dragging_ && ctx.doc.dragging()) ctx.doc.cancel_drag();
  dragging_ = captured_ = false;
}

}  // namespace pl
