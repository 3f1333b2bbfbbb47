#include "app/editor/logic/curvature_graph.hpp"

#include <algorithm>
#include <cmath>

#include "core/curve/curvature.hpp"

namespace pl {

CurvatureGraph curvature_graph(const SceneCurve& curve, int per_span) {
  CurvatureGraph g;
  for (double t : curve_sample_parameters(curve, per_span)) {
    const double k = curve_curvature(evaluate(curve, t));
    g.t.push_back(t);
    g.kappa.push_back(std::isfinite(k) ? k : 0.0);
  }
  if (!g.kappa.empty()) {
    const auto [lo, hi] = std::minmax_element(g.kappa.begin(), g.kappa.end());
    g.kappa_min = *lo, g.kappa_max = *hi;
  }
  const auto spans = curve_spans(curve);
  for (std::size_t i = 1; i < spans.size(); ++i) g.knots.push_back(spans[i].first);
  return g;
}

}  // namespace pl
