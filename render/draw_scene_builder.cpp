#include "render/draw_scene_builder.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "core/analysis/curve_analysis.hpp"
#include "core/base/parallel_for.hpp"
#include "core/patch/control_net_topology.hpp"
#include "core/patch/side_curve.hpp"

namespace pl {

namespace {

uint32_t add_point(ControlNet& net, const Vec3& p, ControlPointKind kind, PointRole role) {
  net.points.push_back(p);
  net.kinds.push_back(kind);
  net.roles.push_back(role);
  return static_cast<uint32_t>(net.points.size() - 1);
}

// Exact positions of the points already in the net (the network's), so that a face patch's
// boundary points, which are copies of them, join the network's points instead of doubling them.
using PointIndex = std::map<std::array<double, 3>, uint32_t>;

std::array<double, 3> key(const Vec3& p) {
  return {p.x, p.y, p.z};
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

void append_patch_net(DrawScene& d, const Patch& p, PointRole role,
                      const std::map<std::array<double, 3>, uint32_t>* shared) {
  const ControlNetTopology t = control_net_topology(p);
  std::vector<uint32_t> id(p.size(), 0);
  for (std::size_t k = 0; k < p.size(); ++k) {
    if (t.is_vector[k]) continue;
    if (shared) {
      const auto it = shared->find(key(p.control_point(k)));
      if (it != shared->end()) {
        id[k] = it->second;
        continue;
      }
    }
    id[k] = add_point(d.net, p.control_point(k), p.kind(k), role);
  }
  for (const auto& s : t.segments) d.net.segments.push_back({id[s[0]], id[s[1]]});
  for (const DerivativeArrow& a : t.arrows)
    d.arrows.push_back({p.control_point(a.base), arrow_tip(p, a), a.kind});
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

int free_curve_samples_per_span(const SceneCurve& c) {
  return std::max(8, kCurveSegments / static_cast<int>(curve_spans(c).size()));
}

Polyline free_curve_polyline(const SceneCurve& c) {
  return free_curve_polyline(c, free_curve_samples_per_span(c));
}

Polyline free_curve_polyline(const SceneCurve& c, int per_span) {
  Polyline l;
  const std::vector<double> ts = curve_sample_parameters(c, per_span);
  l.reserve(ts.size());
  int span = -1;
  for (double t : ts) l.push_back(evaluate(c, t, span).p);
  return l;
}

std::vector<int> free_curves_samples_per_span(std::span<const SceneCurve> curves) {
  std::vector<int> own;
  std::size_t segments = 0;
  for (const SceneCurve& c : curves) {
    own.push_back(free_curve_samples_per_span(c));
    segments += curve_span_count(c) * std::size_t(own.back());
  }
  if (segments <= kFreeCurveSegmentBudget) return own;
  const double size = curves_size(curves);
  constexpr double kPixels = 4096 * 1.4142135623730951 / 2;  // 2 px a segment
  for (std::size_t i = 0; i < curves.size(); ++i) {
    const SceneCurve& c = curves[i];
    const bool control =
        c.type == CurveType::BSpline || c.type == CurveType::Nurbs || c.type == CurveType::Bezier;
    const std::vector<Vec3>& points = control ? c.points : spline_form(c).points;
    double polygon = 0;
    for (std::size_t k = 1; k < points.size(); ++k)
      polygon += glm::length(points[k] - points[k - 1]);
    const double wanted = size > 0 ? polygon / size * kPixels / double(curve_span_count(c)) : 1.0;
    own[i] = std::clamp(static_cast<int>(std::ceil(std::min(wanted, 1e9))), 1, own[i]);
  }
  return own;
}

CurvatureComb free_curve_span_comb(const SceneCurve& c, std::pair<double, double> span,
                                   int comb_teeth) {
  const double a = span.first, len = span.second - span.first;
  int knot_span = -1;
  return curvature_comb(
      [&](double u) {
        CurvePoint p = evaluate(c, a + len * u, knot_span);
        p.d1 *= len, p.d2 *= len * len;  // derivatives in u (the comb needs their direction)
        return p;
      },
      comb_teeth);
}

std::vector<CurvatureComb> free_curve_combs(const SceneCurve& c, int comb_teeth) {
  std::vector<CurvatureComb> combs;
  for (const auto& span : curve_spans(c))
    combs.push_back(free_curve_span_comb(c, span, comb_teeth));
  return combs;
}

void append_free_curve(DrawScene& d, const SceneCurve& c, int comb_teeth) {
  append_free_curve(d, c, comb_teeth, free_curve_samples_per_span(c));
}

void append_free_curve(DrawScene& d, const SceneCurve& c, int comb_teeth, int per_span) {
  d.free_curves.push_back(free_curve_polyline(c, per_span));
  if (comb_teeth > 0)
    for (CurvatureComb& comb : free_curve_combs(c, comb_teeth))
      d.free_curve_combs.push_back(std::move(comb));
  // The control polygon; a Hermite curve's tangents as arrows to its equivalent Bézier handles.
  uint32_t previous = 0;
  for (std::size_t i = 0; i < c.points.size(); ++i) {
    const uint32_t id = add_point(d.net, c.points[i], ControlPointKind::Curve, PointRole::Editable);
    if (i > 0 && c.type != CurveType::Hermite) d.net.segments.push_back({previous, id});
    previous = id;
  }
  if (c.type == CurveType::Hermite) {
    d.arrows.push_back({c.points[0], c.points[0] + c.tangents[0] / 3.0, ArrowKind::Tangent});
    d.arrows.push_back({c.points[1], c.points[1] - c.tangents[1] / 3.0, ArrowKind::Tangent});
  }
}

int closed_orientation(const Scene& scene, const SceneSurfaces& surfaces,
                       const std::vector<SurfaceMesh>& meshes) {
  if (!scene.network || !scene.patches.empty() || scene.network->faces.empty()) return 0;
  if (surfaces.shared_edges.size() != scene.network->edges.size()) return 0;
  for (const SceneSurface& s : surfaces.surfaces)
    if (s.face < 0) return 0;
  return enclosed_volume_sign(meshes);
}

DrawScene build_draw_scene(const Scene& scene, const SceneSurfaces& surfaces, int comb_teeth) {
  DrawScene d;
  const std::vector<int> per_span = free_curves_samples_per_span(scene.curves);
  for (std::size_t i = 0; i < scene.curves.size(); ++i)
    append_free_curve(d, scene.curves[i], comb_teeth, per_span[i]);
  d.surfaces.resize(surfaces.surfaces.size());
  parallel_each(d.surfaces.size(), 4, [&](std::size_t i) {
    d.surfaces[i] = make_surface_mesh(*surfaces.surfaces[i].evaluator, surfaces.surfaces[i].name);
  });
  for (const SceneSurface& s : surfaces.surfaces) {
    for (CurvatureComb& c : surface_borders(s, comb_teeth)) {
      d.borders.push_back(c.points);
      if (comb_teeth > 0) {
        d.border_combs.push_back(std::move(c));
        d.border_on_network.push_back(s.face >= 0);
      }
    }
  }
  PointIndex network_points;
  if (scene.network) {
    const Network& net = *scene.network;
    // The network's own control polygon: vertices and edge handles, what a designer drags.
    std::vector<uint32_t> vertex_ids;
    auto add = [&](const Vec3& p) {
      const uint32_t id = add_point(d.net, p, ControlPointKind::Boundary, PointRole::Editable);
      network_points.emplace(key(p), id);
      return id;
    };
    for (const Vec3& v : net.vertices) vertex_ids.push_back(add(v));
    for (const NetworkEdge& edge : net.edges) {
      const uint32_t h1 = add(edge.handles[0]), h2 = add(edge.handles[1]);
      d.net.segments.push_back({vertex_ids.at(edge.v[0]), h1});
      d.net.segments.push_back({h1, h2});
      d.net.segments.push_back({h2, vertex_ids.at(edge.v[1])});
    }
    d.network_curves = network_polylines(net);
    if (comb_teeth > 0) d.network_combs = network_combs(net, comb_teeth);
  }
  // Explicit patches once each (a Catmull–Clark surface is several surfaces of one patch); their
  // points are the user's. A network face's points are derived from the network, except the
  // boundary points that are the network's own.
  for (const ScenePatch& p : scene.patches) append_patch_net(d, *p.patch, PointRole::Editable);
  for (const SceneSurface& s : surfaces.surfaces)
    if (s.face >= 0) append_patch_net(d, s.evaluator->patch(), PointRole::Derived, &network_points);
  d.closed_orientation = closed_orientation(scene, surfaces, d.surfaces);
  return d;
}

}  // namespace pl
