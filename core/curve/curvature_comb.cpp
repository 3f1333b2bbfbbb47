#include "core/curve/curvature_comb.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace pl {

namespace {
// Relative size of the rounding left by projecting C'' off the tangent (a few ulps).
constexpr double kRoundingLevel = 64 * 2.220446049250313e-16;
// Curvatures whose radius exceeds the scene diagonal this many times are straight to the eye and
// must not set the automatic scale (they would blow every other tooth up).
constexpr double kStraightRadius = 1e9;

double max_abs(const Vec3& v) {
  return std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
}
}  // namespace

Vec3 curvature_tooth(const CurvePoint& c) {
  const double speed2 = glm::dot(c.d1, c.d1);
  // A speed at the rounding level of the point's own coordinates (a pole of a rational sphere,
  // coincident control points) is zero: dividing rounding noise by its square would give a
  // tooth of any length in any direction.
  const double speed_floor = kRoundingLevel * (max_abs(c.p) + max_abs(c.d2));
  if (!(speed2 > speed_floor * speed_floor)) return Vec3(0);
  // The part of C'' across the tangent over |C'|^2 is kappa N; computing it this way needs no
  // division by |C' x C''|, so a straight stretch gives an exact zero rather than 0/0.
  const Vec3 across = c.d2 - (glm::dot(c.d2, c.d1) / speed2) * c.d1;
  // On a straight stretch with C'' along C' (unevenly spaced collinear control points) the
  // subtraction leaves rounding noise of random direction: that is zero curvature, not a tooth.
  if (glm::length(across) <= kRoundingLevel * glm::length(c.d2)) return Vec3(0);
  const Vec3 tooth = -across / speed2;
  if (!finite(tooth))
    return Vec3(0);  // |C'| so small that the quotient overflows: no meaningful curvature
  return tooth;
}

int curvature_comb_intervals(int teeth) {
  if (teeth < 1)
    throw std::invalid_argument("curvature_comb: teeth must be at least 1, got " +
                                std::to_string(teeth));
  return teeth * ((kMinCombEnvelopeSegments + teeth - 1) / teeth);
}

CurvatureComb curvature_comb_of_samples(std::span<const CurvePoint> samples, int teeth) {
  const int n = curvature_comb_intervals(teeth);
  if (samples.size() != std::size_t(n) + 1)
    throw std::invalid_argument("curvature_comb: " + std::to_string(samples.size()) +
                                " samples for " + std::to_string(teeth) + " teeth, expected " +
                                std::to_string(n + 1));
  CurvatureComb comb;
  comb.tooth_stride = n / teeth;
  comb.points.reserve(samples.size());
  comb.teeth.reserve(samples.size());
  for (const CurvePoint& c : samples) {
    comb.points.push_back(c.p);
    comb.teeth.push_back(curvature_tooth(c));
  }
  return comb;
}

CurvatureComb curvature_comb(const std::function<CurvePoint(double)>& curve, int teeth) {
  const int n = curvature_comb_intervals(teeth);
  std::vector<CurvePoint> samples;
  samples.reserve(n + 1);
  // k / n rather than k * (1 / n): the ends are exactly 0 and 1, where curves are joined.
  for (int i = 0; i <= n; ++i) samples.push_back(curve(double(i) / n));
  return curvature_comb_of_samples(samples, teeth);
}

CurvatureComb curvature_comb(const BezierCurve& curve, int teeth) {
  return curvature_comb([&](double t) { return curve.evaluate(t); }, teeth);
}

double automatic_comb_scale(std::span<const CurvatureComb> combs, double diagonal,
                            double fraction) {
  std::vector<const CurvatureComb*> all;
  all.reserve(combs.size());
  for (const CurvatureComb& c : combs) all.push_back(&c);
  return automatic_comb_scale_of(all, diagonal, fraction);
}

double automatic_comb_scale_of(std::span<const CurvatureComb* const> combs, double diagonal,
                               double fraction) {
  std::vector<double> kappa;
  for (const CurvatureComb* c : combs)
    for (const Vec3& t : c->teeth)
      if (const double k = glm::length(t); k * diagonal * kStraightRadius > 1) kappa.push_back(k);
  if (kappa.empty() || !(diagonal > 0)) return 0;
  const std::size_t at =
      std::min(kappa.size() - 1, std::size_t(kCombPercentile * double(kappa.size())));
  std::nth_element(kappa.begin(), kappa.begin() + std::ptrdiff_t(at), kappa.end());
  return fraction * diagonal / kappa[at];
}

}  // namespace pl
