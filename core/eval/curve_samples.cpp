#include "core/eval/curve_samples.hpp"

#include <algorithm>
#include <stdexcept>

#include "core/math/bspline_basis.hpp"

namespace pl {

CurveSamples::CurveSamples(const SceneCurve& curve, int per_span)
    : spline_(spline_form(curve)), t_(curve_sample_parameters(curve, per_span)) {
  const int p = spline_.degree;
  const std::size_t n = spline_.points.size();
  span_.resize(t_.size());
  basis_.resize(t_.size() * 3 * (p + 1));
  int span = -1;  // the samples run in increasing t: each span is found from the last
  for (std::size_t k = 0; k < t_.size(); ++k) {
    span = find_span(p, spline_.knots, n, t_[k], span);
    const SplineBasis b = spline_basis_at(p, spline_.knots, span, t_[k]);
    span_[k] = b.span;
    for (int r = 0; r <= p; ++r) {
      double* row = &basis_[(k * (p + 1) + r) * 3];
      row[0] = b.d0[r], row[1] = b.d1[r], row[2] = b.d2[r];
    }
  }
  // Samples are in increasing t, so each knot interval's samples are one run.
  first_sample_.assign(n - p + 1, t_.size());
  for (std::size_t k = t_.size(); k-- > 0;) first_sample_[span_[k] - p] = k;
  for (std::size_t s = first_sample_.size() - 1; s-- > 0;)
    first_sample_[s] = std::min(first_sample_[s], first_sample_[s + 1]);
  evaluate_all();
}

void CurveSamples::evaluate_all() {
  samples_.resize(t_.size());
  int span = -1;
  for (std::size_t k = 0; k < t_.size(); ++k)
    samples_[k] = evaluate_spline(spline_.degree, spline_.knots, spline_.points, spline_.weights,
                                  t_[k], span);
}

std::pair<std::size_t, std::size_t> CurveSamples::move_point(std::size_t i, const Vec3& p) {
  if (i >= spline_.points.size()) throw std::out_of_range("no such control point");
  const int deg = spline_.degree;
  const Vec3 delta = p - spline_.points[i];
  spline_.points[i] = p;
  // Point i is non-zero on knot intervals i .. i + p; of those, the ones inside the range.
  const int s0 = std::max<int>(deg, static_cast<int>(i));
  const int s1 =
      std::min<int>(static_cast<int>(spline_.points.size()) - 1, static_cast<int>(i) + deg);
  const std::size_t first = first_sample_[s0 - deg], last = first_sample_[s1 - deg + 1];
  for (std::size_t k = first; k < last; ++k) {
    if (spline_.rational()) {
      samples_[k] = evaluate(spline_, t_[k]);
      continue;
    }
    const int r = static_cast<int>(i) - (span_[k] - deg);
    if (r < 0 || r > deg) continue;
    const double* row = &basis_[(k * (deg + 1) + r) * 3];
    samples_[k].p += row[0] * delta;
    samples_[k].d1 += row[1] * delta;
    samples_[k].d2 += row[2] * delta;
  }
  return {first, last};
}

}  // namespace pl
