#include "app/editor/logic/snapping.hpp"

#include <algorithm>
#include <cmath>
#include <span>

namespace pl {

namespace {

// The best candidate so far: points (vertices, control points, ends, midpoints) beat the curve
// points around them when both are within the radius, else the nearer on screen wins.
struct Best {
  std::optional<Snapped> snapped;
  double distance = INFINITY;
  bool on_curve = true;

  void offer(const WindowProjector& project, const Vec2& pixel, double radius, const Vec3& p,
             SnapKind kind, std::string what, int vertex = -1) {
    const auto at = project(p);
    if (!at) return;
    const double d = glm::length(*at - pixel);
    if (d > radius) return;
    const bool curve = kind == SnapKind::OnCurve;
    if (snapped) {
      if (curve && !on_curve) return;                  // a point within reach beats every curve
      if (curve == on_curve && d >= distance) return;  // of one kind, the nearer wins
    }
    snapped = Snapped{p, kind, std::move(what), vertex};
    distance = d, on_curve = curve;
  }
};

// Whether the cursor is within `radius` of the screen box of `hull` (points whose convex hull
// holds the curve: a Bézier's or a spline's control points, weights being positive). A curve out
// of reach is not searched: a hover then costs a few projections per curve, not a search.
bool within_reach(std::span<const Vec3> hull, const WindowProjector& project, const Vec2& pixel,
                  double radius) {
  Vec2 lo(INFINITY), hi(-INFINITY);
  for (const Vec3& p : hull) {
    const auto at = project(p);
    if (!at) return true;  // partly behind the eye: search it
    lo = glm::min(lo, *at), hi = glm::max(hi, *at);
  }
  return pixel.x >= lo.x - radius && pixel.x <= hi.x + radius && pixel.y >= lo.y - radius &&
         pixel.y <= hi.y + radius;
}

// The parameter of `curve` (t in [a, b]) nearest the cursor on screen: the best of 64 samples,
// then a golden-section search on the screen distance around it (one new distance a step).
template <class Curve>
std::optional<double> nearest_on_screen(const Curve& point_at, double a, double b,
                                        const WindowProjector& project, const Vec2& pixel) {
  constexpr int kSamples = 64, kSteps = 40;
  const auto distance = [&](double t) {
    const auto at = project(point_at(t));
    return at ? glm::length(*at - pixel) : INFINITY;
  };
  int best = -1;
  double best_d = INFINITY;
  for (int k = 0; k <= kSamples; ++k)
    if (const double d = distance(a + (b - a) * k / kSamples); d < best_d) best = k, best_d = d;
  if (best < 0) return std::nullopt;
  double lo = a + (b - a) * std::max(0, best - 1) / kSamples;
  double hi = a + (b - a) * std::min(kSamples, best + 1) / kSamples;
  const double g = (std::sqrt(5.0) - 1) / 2;
  double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
  double d1 = distance(x1), d2 = distance(x2);
  for (int i = 0; i < kSteps; ++i) {
    if (d1 < d2) {
      hi = x2, x2 = x1, d2 = d1;
      x1 = hi - g * (hi - lo), d1 = distance(x1);
    } else {
      lo = x1, x1 = x2, d1 = d2;
      x2 = lo + g * (hi - lo), d2 = distance(x2);
    }
  }
  return 0.5 * (lo + hi);
}

}  // namespace

std::optional<Snapped> snap_to_scene(const Scene& scene, const Camera& camera, const ViewRect& rect,
                                     const Vec2& pixel, double radius) {
  const WindowProjector project(camera, rect);
  Best best;
  auto offer = [&](const Vec3& p, SnapKind kind, std::string what, int vertex = -1) {
    best.offer(project, pixel, radius, p, kind, std::move(what), vertex);
  };
  if (scene.network) {
    const Network& n = *scene.network;
    for (std::size_t v = 0; v < n.vertices.size(); ++v)
      offer(n.vertices[v], SnapKind::Vertex, "vertex " + std::to_string(v), int(v));
    for (std::size_t e = 0; e < n.edges.size(); ++e) {
      const BezierCurve c = n.edge_curve(int(e));
      if (!within_reach(c.control_points(), project, pixel, radius)) continue;
      const std::string name = "edge " + std::to_string(e);
      offer(c.point(0.5), SnapKind::Midpoint, name + " midpoint");
      if (const auto t =
              nearest_on_screen([&](double u) { return c.point(u); }, 0.0, 1.0, project, pixel))
        offer(c.point(*t), SnapKind::OnCurve, "on " + name);
    }
  }
  for (std::size_t i = 0; i < scene.curves.size(); ++i) {
    const SceneCurve& c = scene.curves[i];
    // Every candidate of a curve lies in the hull of its control points (its stored points for
    // the Bézier and spline types; the interpolating and Hermite cubics' are their spline form's).
    const bool own_hull = c.type != CurveType::Interpolating && c.type != CurveType::Hermite;
    if (!within_reach(own_hull ? c.points : spline_form(c).points, project, pixel, radius))
      continue;
    const std::string name = "curve " + std::to_string(i);
    for (std::size_t k = 0; k < c.points.size(); ++k)
      offer(c.points[k], SnapKind::CurvePoint, name + " point " + std::to_string(k));
    offer(evaluate(c, c.t_min()).p, SnapKind::End, name + " start");
    offer(evaluate(c, c.t_max()).p, SnapKind::End, name + " end");
    offer(evaluate(c, 0.5 * (c.t_min() + c.t_max())).p, SnapKind::Midpoint, name + " midpoint");
    if (const auto t = nearest_on_screen([&](double u) { return evaluate(c, u).p; }, c.t_min(),
                                         c.t_max(), project, pixel))
      offer(evaluate(c, *t).p, SnapKind::OnCurve, "on " + name);
  }
  return best.snapped;
}

std::optional<Snapped> snap_to_grid(const WorkPlane& plane, const Camera& camera,
                                    const ViewRect& rect, const Vec2& pixel) {
  const auto hit = plane.hit(camera, window_ray(camera, rect, pixel));
  if (!hit) return std::nullopt;
  return Snapped{nearest_grid_point(plane.frame(camera), *hit, shown_grid_step(camera)),
                 SnapKind::Grid, "grid"};
}

}  // namespace pl
