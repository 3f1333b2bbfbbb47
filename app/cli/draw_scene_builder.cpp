#include "app/cli/draw_scene_builder.hpp"

#include "core/patch/bezier_patch.hpp"
#include "core/patch/side_curve.hpp"

namespace pl {

namespace {

uint32_t add_point(ControlNet& net, const Vec3& p, ControlPointKind kind) {
  net.points.push_back(p);
  net.kinds.push_back(kind);
  return static_cast<uint32_t>(net.points.size() - 1);
}

// A tensor-product Bézier net: every point, and the rows and columns of the grid.
void add_bezier_net(ControlNet& net, const BezierPatch& b) {
  const int m = b.degree_u(), n = b.degree_v();
  const auto base = static_cast<uint32_t>(net.points.size());
  for (std::size_t k = 0; k < b.size(); ++k) add_point(net, b.control_point(k), b.kind(k));
  auto id = [&](int i, int j) { return base + static_cast<uint32_t>(i * (n + 1) + j); };
  for (int i = 0; i <= m; ++i)
    for (int j = 0; j <= n; ++j) {
      if (i < m) net.segments.push_back({id(i, j), id(i + 1, j)});
      if (j < n) net.segments.push_back({id(i, j), id(i, j + 1)});
    }
}

}  // namespace

Polyline curve_polyline(const BezierCurve& c, int segments) {
  Polyline l;
  l.reserve(segments + 1);
  for (int i = 0; i <= segments; ++i) l.push_back(c.point(double(i) / segments));
  return l;
}

Polyline edge_polyline(const Network& network, int e, int segments) {
  return curve_polyline(network.edge_curve(e), segments);
}

std::vector<Polyline> network_polylines(const Network& network) {
  std::vector<Polyline> lines;
  for (std::size_t e = 0; e < network.edges.size(); ++e)
    lines.push_back(edge_polyline(network, static_cast<int>(e)));
  return lines;
}

std::vector<CurvatureComb> network_combs(const Network& network, int comb_teeth) {
  std::vector<CurvatureComb> combs;
  for (std::size_t e = 0; e < network.edges.size(); ++e)
    combs.push_back(curvature_comb(network.edge_curve(static_cast<int>(e)), comb_teeth));
  return combs;
}

std::vector<CurvatureComb> surface_borders(const SceneSurface& surface, int comb_teeth) {
  const Patch& patch = surface.evaluator->patch();
  if (comb_teeth > 0) return side_combs(patch, comb_teeth);
  std::vector<CurvatureComb> borders(patch.domain().side_count());
  for (int side = 0; side < int(borders.size()); ++side)
    borders[side].points = side_polyline(patch, side, kCurveSegments);
  return borders;
}

DrawScene build_draw_scene(const Scene& scene, const SceneSurfaces& surfaces, int comb_teeth) {
  DrawScene d;
  for (const SceneSurface& s : surfaces.surfaces) {
    d.surfaces.push_back(make_surface_mesh(*s.evaluator, s.name));
    for (CurvatureComb& c : surface_borders(s, comb_teeth)) {
      d.borders.push_back(c.points);
      if (comb_teeth > 0) {
        d.border_combs.push_back(std::move(c));
        d.border_on_network.push_back(s.face >= 0);
      }
    }
  }
  if (scene.network) {
    const Network& net = *scene.network;
    // The network's own control polygon: vertices and edge handles, what a designer drags.
    std::vector<uint32_t> vertex_ids;
    for (const Vec3& v : net.vertices)
      vertex_ids.push_back(add_point(d.net, v, ControlPointKind::Boundary));
    for (std::size_t e = 0; e < net.edges.size(); ++e) {
      const NetworkEdge& edge = net.edges[e];
      const uint32_t h1 = add_point(d.net, edge.handles[0], ControlPointKind::Boundary);
      const uint32_t h2 = add_point(d.net, edge.handles[1], ControlPointKind::Boundary);
      d.net.segments.push_back({vertex_ids.at(edge.v[0]), h1});
      d.net.segments.push_back({h1, h2});
      d.net.segments.push_back({h2, vertex_ids.at(edge.v[1])});
    }
    d.network_curves = network_polylines(net);
    if (comb_teeth > 0) d.network_combs = network_combs(net, comb_teeth);
  }
  for (const SceneSurface& s : surfaces.surfaces) {
    const Patch& p = s.evaluator->patch();
    if (const auto* b = dynamic_cast<const BezierPatch*>(&p)) {
      add_bezier_net(d.net, *b);
      continue;
    }
    // Other patch types have no grid to draw: show their points by kind. On network faces the
    // boundary points are the network's, already drawn above.
    for (std::size_t k = 0; k < p.size(); ++k)
      if (s.face < 0 || p.kind(k) != ControlPointKind::Boundary)
        add_point(d.net, p.control_point(k), p.kind(k));
  }
  return d;
}

}  // namespace pl
