#include "app/editor/logic/curve_edits.hpp"

#include <algorithm>

namespace pl {

bool same_but_points(const SceneCurve& a, const SceneCurve& b) {
  return a.type == b.type && a.degree == b.degree && a.knots == b.knots && a.weights == b.weights &&
         a.tangents == b.tangents && a.name == b.name && a.points.size() == b.points.size();
}

std::optional<std::pair<double, double>> moved_range(const SceneCurve& before,
                                                     const SceneCurve& now) {
  const bool spline = now.type == CurveType::BSpline || now.type == CurveType::Nurbs;
  std::optional<std::pair<double, double>> range;
  for (std::size_t k = 0; k < now.points.size() && k < before.points.size(); ++k) {
    if (before.points[k] == now.points[k]) continue;
    const double lo = spline ? now.knots[k] : now.t_min();
    const double hi = spline ? now.knots[k + now.degree + 1] : now.t_max();
    range = range ? std::pair{std::min(range->first, lo), std::max(range->second, hi)}
                  : std::pair{lo, hi};
  }
  return range;
}

}  // namespace pl
