// The samples of a free curve kept up to date through edits: moving one control point of a
// B-spline of degree p changes the curve on p + 1 knot intervals only, so only the samples there
// are recomputed (for a polynomial spline an axpy with the cached basis value of that point,
// for a rational one a fresh evaluation of those samples). The cost of a drag does not grow with
// the length of the curve.
#pragma once

#include <vector>

#include "core/curve/scene_curve.hpp"

namespace pl {

class CurveSamples {
 public:
  // per_span + 1 samples in each span (curve_sample_parameters).
  CurveSamples(const SceneCurve& curve, int per_span);

  const SplineCurve& spline() const { return spline_; }
  const std::vector<double>& parameters() const { return t_; }
  const std::vector<CurvePoint>& samples() const { return samples_; }

  // Moves control point i of the B-spline form to p and updates the samples it moves. Returns
  // the range [first, last) of samples that changed.
  std::pair<std::size_t, std::size_t> move_point(std::size_t i, const Vec3& p);
  // Every sample evaluated again (the reference of the incremental path).
  void evaluate_all();

 private:
  SplineCurve spline_;
  std::vector<double> t_;
  std::vector<int> span_;  // knot interval index s of each sample (knots[s] <= t < knots[s+1])
  std::vector<CurvePoint> samples_;
  // Per sample, the basis values (N, N', N'') of the p + 1 points of its span.
  std::vector<double> basis_;
  // first_sample_[s - p]: the first sample in knot interval s (s = p .. n), n = points.
  std::vector<std::size_t> first_sample_;
};

}  // namespace pl
