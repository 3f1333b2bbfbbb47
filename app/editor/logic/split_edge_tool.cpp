#include "app/editor/logic/split_edge_tool.hpp"

namespace pl {

namespace {

// The edge and parameter under the cursor, if a curve is there.
std::optional<std::pair<int, double>> curve_under(const Scene& scene, const PointerEvent& e) {
  if (!e.under || e.under->edge < 0 || !scene.network) return std::nullopt;
  if (e.under->edge >= int(scene.network->edges.size())) return std::nullopt;
  return std::make_pair(e.under->edge, e.under->edge_t);
}

}  // namespace

bool split_edge_at(Document& doc, Selection& selection,
                   const std::function<void(const std::string&)>& say, int e, double t) {
  const int v = doc.scene().network ? int(doc.scene().network->vertices.size()) : 0;
  if (!run_command(doc, say, std::make_shared<SplitEdgeCommand>(e, t))) return false;
  // Old indices keep their objects (edge e now ends at the new vertex): the selection stays.
  selection.adopt(doc.scene());
  selection.set({SelectionItem::of_point(PointRef::vertex(v))});
  return true;
}

std::string SplitEdgeTool::hint() const {
  return "click on a curve: its edge is split there (the curve stays the same; its faces gain a "
         "side)";
}

void SplitEdgeTool::click(ToolContext& ctx, const PointerEvent& e) {
  const auto at = curve_under(ctx.doc.scene(), e);
  if (!at) {
    ctx.say("click on a curve to split its edge there");
    return;
  }
  const auto [edge, t] = *at;
  if (t < kEndMargin || t > 1 - kEndMargin) {
    ctx.say("too close to the end of edge " + std::to_string(edge) + ": click further in");
    return;
  }
  split_edge_at(ctx.doc, ctx.selection, ctx.say, edge, t);
}

void SplitEdgeTool::hover(ToolContext& ctx, const PointerEvent& e) {
  const auto at = curve_under(ctx.doc.scene(), e);
  cursor_.reset();
  if (at) cursor_ = ctx.doc.scene().network->edge_curve(at->first).evaluate(at->second).p;
}

ToolPreview SplitEdgeTool::preview(const ToolContext&) const {
  ToolPreview p;
  p.target = cursor_;
  return p;
}

}  // namespace pl
