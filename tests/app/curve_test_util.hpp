// Shared by the curve tests of the app: a six-point zigzag and the largest distance between two
// curves over 1,000 parameters of the first one's range.
#pragma once

#include <algorithm>
#include <vector>

#include "core/curve/scene_curve.hpp"

namespace pl::test {

inline std::vector<Vec3> six_points() {
  return {{0, 0, 0}, {1, 1, 0}, {2, 0, 0}, {3, 1, 0}, {4, 0, 0}, {5, 1, 0}};
}

inline double max_sample_difference(const SceneCurve& a, const SceneCurve& b) {
  double worst = 0;
  for (int i = 0; i < 1000; ++i) {
    const double t = a.t_min() + (a.t_max() - a.t_min()) * i / 999.0;
    worst = std::max(worst, glm::length(evaluate(a, t).p - evaluate(b, t).p));
  }
  return worst;
}

}  // namespace pl::test
