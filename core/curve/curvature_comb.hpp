// Curvature combs: at samples C(t_i) of a curve, a "tooth" of length proportional to the exact
// curvature kappa = |C' x C''| / |C'|^3, pointing away from the centre of curvature, and the
// envelope through the tooth tips. The usual way to read fairness off a curve: a kink in the
// envelope is a curvature jump, a tooth crossing over is an inflection. GUI-free so that the
// geometry is tested without GL; the renderer draws the arrays as they are.
#pragma once

#include <functional>
#include <span>
#include <vector>

#include "core/curve/bezier_curve.hpp"

namespace pl {

// kappa * (-N) at one curve point, N the principal normal (towards the centre of curvature):
// -(C'' - (C''.T) T) / |C'|^2 with T = C'/|C'|, whose length is kappa. The tooth is drawn away
// from the centre, so it never crosses the curve where the curve bends and a flip of side marks
// an inflection. Zero where the curve is straight there (kappa = 0), where C' vanishes (to the
// rounding level of the point's coordinates: kappa is undefined there) and where the quotient
// would overflow: never NaN or infinite.
Vec3 curvature_tooth(const CurvePoint& c);

struct CurvatureComb {
  std::vector<Vec3> points;  // C(t_i), t_i increasing over [0, 1]
  std::vector<Vec3> teeth;   // curvature_tooth at t_i: the tip is points[i] + scale * teeth[i]
  // A tooth is drawn at every tooth_stride-th sample (the first and the last always have one);
  // the envelope runs through every sample's tip, so it stays smooth with few teeth.
  int tooth_stride = 1;

  Vec3 tip(std::size_t i, double scale) const { return points[i] + scale * teeth[i]; }
};

// Envelope segments a comb has at least, whatever its tooth count: the envelope of a cubic is
// smooth to the eye at this resolution.
constexpr int kMinCombEnvelopeSegments = 64;

// Samples `curve` (position and derivatives in t over [0, 1]) with `teeth` tooth intervals
// (teeth + 1 teeth at t = k / teeth), refined between teeth for the envelope. Throws
// std::invalid_argument unless teeth >= 1.
CurvatureComb curvature_comb(const std::function<CurvePoint(double)>& curve, int teeth);
CurvatureComb curvature_comb(const BezierCurve& curve, int teeth);
// The number n of sample intervals of a comb with `teeth` tooth intervals (samples at t = i / n,
// i = 0..n). Throws std::invalid_argument unless teeth >= 1.
int curvature_comb_intervals(int teeth);
// The comb of samples already taken at t = i / n (n = curvature_comb_intervals(teeth); e.g. in
// one batch). Throws std::invalid_argument for another sample count.
CurvatureComb curvature_comb_of_samples(std::span<const CurvePoint> samples, int teeth);

// The automatic scale: the tooth of the reference curvature, the kCombPercentile quantile of the
// non-zero curvatures over all combs, is kDefaultCombFraction of the scene's bounding box
// diagonal: long enough to read, short enough that combs of neighbouring edges do not tangle.
// A quantile rather than the maximum: a few samples near a cusp (kappa grows without bound
// where C' nearly vanishes, e.g. a badly parameterised Coons side) would otherwise shrink every
// other tooth to nothing. The renderer caps teeth at a few reference lengths for those.
inline constexpr double kCombPercentile = 0.90;
inline constexpr double kDefaultCombFraction = 0.06;

// Tooth length per unit curvature by the rule above; 0 when every comb is straight (no tooth
// has length).
double automatic_comb_scale(std::span<const CurvatureComb> combs, double diagonal,
                            double fraction = kDefaultCombFraction);
// The same over combs held elsewhere (no copies of their arrays).
double automatic_comb_scale_of(std::span<const CurvatureComb* const> combs, double diagonal,
                               double fraction = kDefaultCombFraction);

}  // namespace pl
