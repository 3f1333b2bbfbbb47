// Incremental curve samples: a moved point updates exactly the samples of its p + 1 knot
// intervals, to the numbers a fresh evaluation gives.
#include "core/eval/curve_samples.hpp"

#include <gtest/gtest.h>

#include <random>

namespace pl {
namespace {

SceneCurve random_curve(int p, int n, bool rational, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1), w(0.5, 2);
  SceneCurve c;
  c.type = rational ? CurveType::Nurbs : CurveType::BSpline;
  c.degree = p;
  for (int i = 0; i < n; ++i) c.points.push_back({u(rng), u(rng), u(rng)});
  // Non-uniform knots with one double knot.
  c.knots.assign(p + 1, 0.0);
  double t = 0;
  for (int i = 0; i < n - p - 1; ++i) c.knots.push_back(i == 3 ? t : (t += w(rng)));
  c.knots.insert(c.knots.end(), p + 1, t + 1);
  if (rational)
    for (int i = 0; i < n; ++i) c.weights.push_back(w(rng));
  validate_curve(c);
  return c;
}

TEST(CurveSamples, MovingAPointUpdatesOnlyItsSpans) {
  for (bool rational : {false, true}) {
    const int p = 3, per_span = 8;
    CurveSamples s(random_curve(p, 60, rational, 7), per_span);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-1, 1);
    for (std::size_t i : {0u, 1u, 17u, 30u, 58u, 59u}) {
      const std::vector<CurvePoint> before = s.samples();
      const auto [first, last] = s.move_point(i, {u(rng), u(rng), u(rng)});
      EXPECT_LE(last - first, std::size_t((p + 1) * per_span + 1)) << i;
      for (std::size_t k = 0; k < before.size(); ++k)
        if (k < first || k >= last) {
          EXPECT_EQ(s.samples()[k].p, before[k].p) << k;
        }
      // A fresh evaluation of the moved curve: equal up to rounding of the axpy.
      for (std::size_t k = 0; k < before.size(); ++k) {
        const CurvePoint e = evaluate(s.spline(), s.parameters()[k]);
        EXPECT_LT(glm::length(s.samples()[k].p - e.p), 1e-14 * 4) << k;
        EXPECT_LT(glm::length(s.samples()[k].d1 - e.d1), 1e-12 * (1 + glm::length(e.d1))) << k;
      }
    }
  }
}

}  // namespace
}  // namespace pl
