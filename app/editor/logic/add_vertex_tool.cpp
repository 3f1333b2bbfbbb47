#include "app/editor/logic/add_vertex_tool.hpp"

#include <cmath>

namespace pl {

std::string AddVertexTool::hint() const {
  return "click on the work plane or on a surface: a new vertex there (Shift keeps the "
         "selection); or type its coordinates below";
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
  const auto p = placement(ctx, e);
  if (!p) {
    ctx.say("the cursor does not meet the work plane here: turn the view or choose another plane");
    return;
  }
  add_at(ctx, *p, e.shift);
}

ToolPreview AddVertexTool::preview(const ToolContext&) const {
  ToolPreview p;
  p.target = cursor_;
  return p;
}

}  // namespace pl
