#include "app/editor/logic/add_edge_tool.hpp"

namespace pl {

namespace {

bool vertex_exists(const Scene& scene, int v) {
  return scene.network && v >= 0 && v < int(scene.network->vertices.size());
}

}  // namespace

std::string AddEdgeTool::hint() const {
  return "click a vertex, then another: an edge joins them, and the next edge starts there "
         "(click empty space or Esc to stop)";
}

void AddEdgeTool::click(ToolContext& ctx, const PointerEvent& e) {
  if (!vertex_exists(ctx.doc.scene(), from_)) from_ = -1;  // an undo took it away
  const int v = vertex_under(e);
  if (v < 0) {
    if (from_ >= 0) ctx.say("edge chain ended");
    from_ = -1;
    return;
  }
  if (from_ < 0 || v == from_) {
    if (v == from_) {
      from_ = -1;
      ctx.say("edge chain ended");
      return;
    }
    from_ = v;
    ctx.selection.set({SelectionItem::of_point(PointRef::vertex(v))});
    ctx.say("edge from vertex " + std::to_string(v) + ": click the vertex at its other end");
    return;
  }
  if (!run_command(ctx, std::make_shared<AddEdgeCommand>(from_, v))) return;
  from_ = v;
  ctx.selection.set({SelectionItem::of_point(PointRef::vertex(v))});
}

void AddEdgeTool::hover(ToolContext& ctx, const PointerEvent& e) {
  const int v = vertex_under(e);
  cursor_ = v >= 0 && vertex_exists(ctx.doc.scene(), v) ? ctx.doc.scene().network->vertices[v]
                                                        : placement(ctx, e);
}

ToolPreview AddEdgeTool::preview(const ToolContext& ctx) const {
  ToolPreview p;
  if (!vertex_exists(ctx.doc.scene(), from_)) return p;
  const Vec3 a = ctx.doc.scene().network->vertices[from_];
  p.picked.push_back(a);
  if (cursor_) p.pending.push_back({a, *cursor_});
  return p;
}

}  // namespace pl
