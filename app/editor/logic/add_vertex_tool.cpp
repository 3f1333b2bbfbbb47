#include "app/editor/logic/add_vertex_tool.hpp"

#include <cmath>

namespace pl {

std::string AddVertexTool::hint() const {
  return "click on the work plane or on a surface: a new vertex there (Shift keeps the "
         "selection; on a vertex: that vertex is selected); or type its coordinates below";
}

int AddVertexTool::add_at(ToolContext& ctx, const Vec3& p, bool add_to_selection) {
  if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
    ctx.say("refused: a vertex needs finite coordinates");
    return -1;
  }
  const Scene& scene = ctx.doc.scene();
  const int v = scene.network ? int(scene.network->vertices.size()) : 0;  // appended
  if (!run_command(ctx, std::make_shared<AddVertexCommand>(p))) return -1;
  const SelectionItem item = SelectionItem::of_point(PointRef::vertex(v));
  if (add_to_selection)
    ctx.selection.add(item);
  else
    ctx.selection.set({item});
  return v;
}

void AddVertexTool::click(ToolContext& ctx, const PointerEvent& e) {
  // A click on a vertex takes that vertex (the hover names it, or snapping lands on it) instead
  // of a near-duplicate a hair beside it: selected, or with Shift added to the selection, as a
  // new vertex would be, so a chain being collected for a face can go through it.
  const std::optional<Snapped> snapped = snapping(ctx, e);
  int v = vertex_under(e);
  if (v < 0 && snapped) v = snapped->vertex;
  if (v >= 0) {
    const SelectionItem item = SelectionItem::of_point(PointRef::vertex(v));
    if (e.shift)
      ctx.selection.add(item);
    else
      ctx.selection.set({item});
    ctx.say("vertex " + std::to_string(v) + " is already here: " +
            (e.shift ? "added it to the selection" : "selected it") + ", no new vertex");
    return;
  }
  const auto p = placement(ctx, e, snapped);
  if (!p) {
    ctx.say("the cursor does not meet the work plane here: turn the view or choose another plane");
    return;
  }
  if (add_at(ctx, *p, e.shift) >= 0 && snapped)
    ctx.say(ctx.doc.undo_label() + " (snapped to " + snapped->what + ")");
}

void AddVertexTool::hover(ToolContext& ctx, const PointerEvent& e) {
  // Over a vertex the mark sits on it: a click takes it, it adds nothing beside it.
  const int v = vertex_under(e);
  const Scene& scene = ctx.doc.scene();
  if (v >= 0 && scene.network && v < int(scene.network->vertices.size())) {
    cursor_ = scene.network->vertices[v];
    return;
  }
  // What the point would snap to, said once as it changes (not every frame).
  const std::optional<Snapped> s = snapping(ctx, e);
  cursor_ = placement(ctx, e, s);
  const std::string what = s ? s->what : "";
  if (what != snapped_to_ && !what.empty() && what != "grid") ctx.say("snap: " + what);
  snapped_to_ = what;
}

ToolPreview AddVertexTool::preview(const ToolContext&) const {
  ToolPreview p;
  p.target = cursor_;
  return p;
}

}  // namespace pl
