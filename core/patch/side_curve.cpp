#include "core/patch/side_curve.hpp"

#include <stdexcept>
#include <string>

namespace pl {

namespace {

// The limit of C'' at a side's end is extrapolated from C'' at h, 2h, 3h inside the side
// (quadratic: error about h^3 |C^(5)|, plus rounding that grows like 1/h^2 on patches whose
// evaluation loses digits near a corner), and replaces the corner jet's only where the two
// disagree by more than kCornerTolerance relative: more than extrapolation error, far less than
// a direction-dependent corner Hessian (GB corners: tens of percent).
constexpr double kEndStep = 1e-4;
constexpr double kCornerTolerance = 1e-6;

// The curve's derivatives along the domain direction d from the surface jet.
CurvePoint along(const SurfaceJet& s, Vec2 d) {
  return {s.p, d.x * s.su + d.y * s.sv,
          d.x * d.x * s.suu + 2 * d.x * d.y * s.suv + d.y * d.y * s.svv};
}

CurvePoint along_side(const Patch& patch, Vec2 d, Vec2 x) {
  return along(patch.evaluate(x), d);
}

}  // namespace

CurvePoint side_curve_point(const Patch& patch, int side, double t) {
  const Domain& domain = patch.domain();
  // Every domain side is a straight segment (Domain::side_point interpolates its end vertices
  // linearly), so its direction is constant.
  const Vec2 d = domain.side_point(side, 1.0) - domain.side_point(side, 0.0);
  CurvePoint c = along_side(patch, d, domain.side_point(side, t));
  if (t == 0.0 || t == 1.0) {
    // At a domain vertex evaluate() may return the limit of the Hessian along another direction:
    // a GB patch's corner jet is its limit towards the domain's interior point, and the second
    // derivative along the side differs there (7.8 against 39.6 on a side of the dome3 reference
    // patch). The side curve's C'' is the limit along the side.
    const double h = t == 0.0 ? kEndStep : -kEndStep;
    Vec3 d2[3];
    for (int k = 0; k < 3; ++k)
      d2[k] = along_side(patch, d, domain.side_point(side, t + (k + 1) * h)).d2;
    const Vec3 limit = 3.0 * d2[0] - 3.0 * d2[1] + d2[2];
    const double scale = glm::length(c.d2) + glm::length(c.d1);
    if (glm::length(limit - c.d2) > kCornerTolerance * scale) c.d2 = limit;
  }
  return c;
}

CurvatureComb side_comb(const Patch& patch, int side, int teeth) {
  const int n = curvature_comb_intervals(teeth);
  const Domain& domain = patch.domain();
  const Vec2 d = domain.side_point(side, 1.0) - domain.side_point(side, 0.0);
  // The inner samples in one evaluate_many (batched for GB patches, several samples per SIMD
  // block); the two ends one by one, with their corner limit (side_curve_point).
  std::vector<Vec2> xs;
  xs.reserve(n > 1 ? n - 1 : 0);
  for (int i = 1; i < n; ++i) xs.push_back(domain.side_point(side, double(i) / n));
  std::vector<SurfaceJet> jets(xs.size());
  patch.evaluate_many(xs, jets);
  std::vector<CurvePoint> samples;
  samples.reserve(n + 1);
  samples.push_back(side_curve_point(patch, side, 0.0));
  for (const SurfaceJet& j : jets) samples.push_back(along(j, d));
  samples.push_back(side_curve_point(patch, side, 1.0));
  return curvature_comb_of_samples(samples, teeth);
}

std::vector<Vec3> side_polyline(const Patch& patch, int side, int segments) {
  if (segments < 1)
    throw std::invalid_argument("side_polyline: segments must be at least 1, got " +
                                std::to_string(segments));
  std::vector<Vec2> xs(std::size_t(segments) + 1);
  for (int i = 0; i <= segments; ++i)
    xs[i] = patch.domain().side_point(side, double(i) / segments);  // ends exactly 0 and 1
  std::vector<SurfaceJet> jets(xs.size());
  patch.evaluate_many(xs, jets);
  std::vector<Vec3> points;
  points.reserve(jets.size());
  for (const SurfaceJet& j : jets) points.push_back(j.p);
  return points;
}

std::vector<CurvatureComb> side_combs(const Patch& patch, int teeth) {
  std::vector<CurvatureComb> combs;
  for (int side = 0; side < patch.domain().side_count(); ++side)
    combs.push_back(side_comb(patch, side, teeth));
  return combs;
}

}  // namespace pl
