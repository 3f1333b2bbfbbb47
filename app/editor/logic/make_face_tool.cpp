#include "app/editor/logic/make_face_tool.hpp"

#include <algorithm>

namespace pl {

namespace {

// Points along edge e's curve, for drawing a picked edge.
std::vector<Vec3> curve_points(const Network& n, int e) {
  constexpr int kSegments = 24;
  const BezierCurve c = n.edge_curve(e);
  std::vector<Vec3> line;
  for (int i = 0; i <= kSegments; ++i) line.push_back(c.evaluate(double(i) / kSegments).p);
  return line;
}

}  // namespace

Vec3 towards_viewer(const Camera& camera) {
  return -camera.forward();
}

std::string MakeFaceTool::hint() const {
  return "click the vertices of a closed chain in order (or its edges); Enter or a click on the "
         "first vertex makes the face; Esc drops the chain";
}

bool MakeFaceTool::valid(const Scene& scene) const {
  if (!scene.network) return vertices_.empty() && edges_.empty();
  const Network& n = *scene.network;
  return std::all_of(vertices_.begin(), vertices_.end(),
                     [&](int v) { return v < int(n.vertices.size()); }) &&
         std::all_of(edges_.begin(), edges_.end(), [&](int e) { return e < int(n.edges.size()); });
}

void MakeFaceTool::cancel(ToolContext&) {
  vertices_.clear();
  edges_.clear();
}

void MakeFaceTool::click(ToolContext& ctx, const PointerEvent& e) {
  if (!valid(ctx.doc.scene())) cancel(ctx);  // an undo took something away
  const int v = vertex_under(e);
  const std::optional<SelectionItem>& item = e.under ? e.under->item : std::nullopt;
  if (v >= 0) {
    if (!edges_.empty()) {
      ctx.say("this face is picked by its edges: click edges, or Esc to start again");
      return;
    }
    if (vertices_.size() >= 3 && v == vertices_.front()) {
      finish(ctx);
      return;
    }
    if (std::find(vertices_.begin(), vertices_.end(), v) != vertices_.end()) {
      ctx.say("vertex " + std::to_string(v) + " is already in the face's chain");
      return;
    }
    vertices_.push_back(v);
    ctx.say("face through " + std::to_string(vertices_.size()) +
            (vertices_.size() >= 3 ? " vertices: Enter or a click on the first one makes it"
                                   : " vertices: click the next one"));
    return;
  }
  if (item && item->kind == SelectionItem::Kind::Edge) {
    if (!vertices_.empty()) {
      ctx.say("this face is picked by its vertices: click vertices, or Esc to start again");
      return;
    }
    const auto at = std::find(edges_.begin(), edges_.end(), item->index);
    if (at != edges_.end())
      edges_.erase(at);
    else
      edges_.push_back(item->index);
    ctx.say("face on " + std::to_string(edges_.size()) + " edges" +
            (edges_.size() >= 3 ? ": Enter makes it" : ": click the next one"));
    return;
  }
  ctx.say("click a vertex or an edge of the face's chain");
}

void MakeFaceTool::hover(ToolContext& ctx, const PointerEvent& e) {
  const int v = vertex_under(e);
  const Scene& s = ctx.doc.scene();
  cursor_ = v >= 0 && s.network && v < int(s.network->vertices.size()) ? s.network->vertices[v]
                                                                       : placement(ctx, e);
}

bool MakeFaceTool::can_finish(const ToolContext& ctx) const {
  return valid(ctx.doc.scene()) && (vertices_.size() >= 3 || edges_.size() >= 3);
}

void MakeFaceTool::finish(ToolContext& ctx) {
  if (!can_finish(ctx)) {
    ctx.say("a face needs a closed chain of at least 3 vertices or edges");
    return;
  }
  const int face = int(ctx.doc.scene().network->faces.size());  // appended
  const Vec3 towards = towards_viewer(ctx.camera);
  std::shared_ptr<MakeFaceCommand> command =
      edges_.empty()
          ? std::make_shared<MakeFaceCommand>(vertices_, towards)
          : std::shared_ptr<MakeFaceCommand>(MakeFaceCommand::from_edges(edges_, towards));
  if (!run_command(ctx, command)) return;  // the chain stays picked, to be put right
  vertices_.clear();
  edges_.clear();
  ctx.selection.set({SelectionItem::face(face)});
}

ToolPreview MakeFaceTool::preview(const ToolContext& ctx) const {
  ToolPreview p;
  const Scene& s = ctx.doc.scene();
  if (!s.network || !valid(s)) return p;
  const Network& n = *s.network;
  for (int e : edges_) p.lines.push_back(curve_points(n, e));
  if (vertices_.empty()) return p;
  std::vector<Vec3> chain;
  for (int v : vertices_) chain.push_back(n.vertices[v]);
  p.picked = chain;
  if (chain.size() > 1) p.lines.push_back(chain);
  if (cursor_) {
    p.pending.push_back({chain.back(), *cursor_});
    if (chain.size() >= 2) p.pending.push_back({*cursor_, chain.front()});
  } else if (chain.size() >= 3) {
    p.pending.push_back({chain.back(), chain.front()});
  }
  return p;
}

}  // namespace pl
