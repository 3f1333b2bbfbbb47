#include "app/editor/logic/selection_properties.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace pl {

namespace {

// 5-point Gauss-Legendre nodes on [-1, 1] and their weights: exact for degree 9.
constexpr std::array<double, 5> kNodes = {0.0, -0.5384693101056831, 0.5384693101056831,
                                          -0.9061798459386640, 0.9061798459386640};
constexpr std::array<double, 5> kWeights = {0.5688888888888889, 0.4786286704993665,
                                            0.4786286704993665, 0.2369268850561891,
                                            0.2369268850561891};

double gauss_length(const BezierCurve& d1, int intervals) {
  double sum = 0;
  const double h = 1.0 / intervals;
  for (int i = 0; i < intervals; ++i) {
    const double mid = (i + 0.5) * h;
    for (std::size_t k = 0; k < kNodes.size(); ++k)
      sum += kWeights[k] * glm::length(d1.point(mid + 0.5 * h * kNodes[k]));
  }
  return 0.5 * h * sum;
}

}  // namespace

double curve_length(const BezierCurve& curve, double relative_tolerance) {
  const BezierCurve d1 = curve.derivative();
  double previous = gauss_length(d1, 4);
  // Doubling stops at 2^14 intervals: only a cusp (|C'| = 0 inside) converges this slowly.
  for (int n = 8; n <= (1 << 14); n *= 2) {
    const double next = gauss_length(d1, n);
    if (std::abs(next - previous) <= relative_tolerance * std::abs(next)) return next;
    previous = next;
  }
  return previous;
}

const char* scheme_name(FaceScheme scheme) {
  switch (scheme) {
    case FaceScheme::Auto:
      return "Auto";
    case FaceScheme::Gregory:
      return "Gregory";
    case FaceScheme::GB:
      return "GB";
    case FaceScheme::SideBased:
      return "Side-based";
    case FaceScheme::CornerBased:
      return "Corner-based";
    case FaceScheme::GeneralizedCoons:
      return "Generalized Coons";
    case FaceScheme::CompositeRibbon:
      return "Composite ribbon";
    case FaceScheme::Midpoint:
      return "Midpoint";
    case FaceScheme::MidpointCoons:
      return "Midpoint Coons";
    case FaceScheme::Elastic:
      return "Elastic";
  }
  return "?";
}

std::optional<FaceProperties> face_properties(const Scene& scene, int face) {
  if (!item_exists(scene, SelectionItem::face(face))) return std::nullopt;
  const NetworkFace& f = scene.network->faces[face];
  FaceProperties p;
  p.face = face;
  p.name = f.name;
  p.sides = int(f.loop.size());
  p.scheme = f.scheme;
  p.resolved = resolve_scheme(f, std::nullopt);
  p.gregory_allowed = p.sides == 3 || p.sides == 4;
  return p;
}

std::optional<EdgeProperties> edge_properties(const Scene& scene, int edge) {
  if (!item_exists(scene, SelectionItem::edge(edge))) return std::nullopt;
  const Network& net = *scene.network;
  const NetworkEdge& e = net.edges[edge];
  EdgeProperties p;
  p.edge = edge;
  p.name = e.name;
  p.from = e.v[0];
  p.to = e.v[1];
  if (e.v[0] >= 0 && e.v[1] >= 0 && e.v[0] < int(net.vertices.size()) &&
      e.v[1] < int(net.vertices.size()))
    p.length = curve_length(net.edge_curve(edge));
  // Face side i joins loop[i] and loop[i+1]; the network has one edge per joined pair.
  for (std::size_t fi = 0; fi < net.faces.size(); ++fi) {
    const std::vector<int>& loop = net.faces[fi].loop;
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const int a = loop[i], b = loop[(i + 1) % loop.size()];
      if ((a == e.v[0] && b == e.v[1]) || (a == e.v[1] && b == e.v[0])) {
        p.faces.push_back(int(fi));
        break;
      }
    }
  }
  return p;
}

std::optional<VertexProperties> vertex_properties(const Scene& scene, int vertex) {
  if (!item_exists(scene, SelectionItem::of_point(PointRef::vertex(vertex)))) return std::nullopt;
  const Network& net = *scene.network;
  VertexProperties p;
  p.vertex = vertex;
  p.position = net.vertices[vertex];
  if (vertex < int(net.normals.size()) && net.normals[vertex]) {
    p.tangent_plane_fixed = true;
    p.normal = net.normals[vertex];
  }
  for (const NetworkEdge& e : net.edges) p.edges += (e.v[0] == vertex) + (e.v[1] == vertex);
  return p;
}

std::optional<PatchProperties> patch_properties(const Scene& scene, int patch) {
  if (!item_exists(scene, SelectionItem::patch(patch))) return std::nullopt;
  const ScenePatch& s = scene.patches[patch];
  PatchProperties p;
  p.patch = patch;
  p.name = s.name;
  p.type = s.patch->type();
  p.points = int(s.patch->size());
  return p;
}

std::vector<std::vector<int>> face_edges(const Network& net, const std::vector<int>& faces) {
  std::vector<std::vector<int>> at_vertex(net.vertices.size());
  for (std::size_t e = 0; e < net.edges.size(); ++e)
    for (int end = 0; end < 2; ++end) {
      const int v = net.edges[e].v[end];
      if (v >= 0 && v < int(at_vertex.size())) at_vertex[v].push_back(int(e));
    }
  std::vector<std::vector<int>> r;
  for (int f : faces) {
    std::vector<int>& sides = r.emplace_back();
    if (f < 0 || f >= int(net.faces.size())) continue;
    const std::vector<int>& loop = net.faces[f].loop;
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const int a = loop[i], b = loop[(i + 1) % loop.size()];
      int found = -1;
      if (a >= 0 && a < int(at_vertex.size()))
        for (int e : at_vertex[a]) {
          const auto& v = net.edges[e].v;
          if ((v[0] == a && v[1] == b) || (v[0] == b && v[1] == a)) found = e;
        }
      sides.push_back(found);
    }
  }
  return r;
}

std::vector<PointRef> points_of(const Scene& scene, const Selection& selection) {
  std::vector<PointRef> r;
  auto add = [&](const PointRef& p) {
    if (point_exists(scene, p) && std::find(r.begin(), r.end(), p) == r.end()) r.push_back(p);
  };
  auto add_edge = [&](int e) {
    const NetworkEdge& edge = scene.network->edges[e];
    add(PointRef::vertex(edge.v[0]));
    add(PointRef::handle(e, 0));
    add(PointRef::handle(e, 1));
    add(PointRef::vertex(edge.v[1]));
  };
  for (const SelectionItem& i : selection.items()) {
    if (!item_exists(scene, i)) continue;
    switch (i.kind) {
      case SelectionItem::Kind::Point:
        add(i.point);
        break;
      case SelectionItem::Kind::Edge:
        add_edge(i.index);
        break;
      case SelectionItem::Kind::Face: {
        const std::vector<std::vector<int>> sides = face_edges(*scene.network, {i.index});
        for (int e : sides[0])
          if (e >= 0) add_edge(e);
        break;
      }
      case SelectionItem::Kind::Patch:
        for (std::size_t k = 0; k < scene.patches[i.index].patch->size(); ++k)
          add(PointRef::patch_point(i.index, int(k)));
        break;
      case SelectionItem::Kind::Curve:
        for (std::size_t k = 0; k < scene.curves[i.index].points.size(); ++k)
          add(PointRef::curve_point(i.index, int(k)));
        break;
    }
  }
  return r;
}

Box selection_bounds(const Scene& scene, const Selection& selection) {
  Box b;
  for (const PointRef& p : points_of(scene, selection)) b.add(point_position(scene, p));
  return b;
}

}  // namespace pl
