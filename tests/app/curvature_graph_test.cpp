// The curvature graph of a free curve against an independent computation: the NURBS circle of
// radius r (the nine-point quadratic) has κ = 1/r at every sample, and a B-spline with a double
// knot shows its knots as ticks.
#include "app/editor/logic/curvature_graph.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace pl::test {
namespace {

TEST(CurvatureGraph, NurbsCircleIsLevelAtOneOverR) {
  const double r = 2.5, h = std::sqrt(0.5);
  SceneCurve c;
  c.type = CurveType::Nurbs;
  c.degree = 2;
  c.points = {{r, 0, 0},   {r, r, 0},  {0, r, 0},  {-r, r, 0}, {-r, 0, 0},
              {-r, -r, 0}, {0, -r, 0}, {r, -r, 0}, {r, 0, 0}};
  c.weights = {1, h, 1, h, 1, h, 1, h, 1};
  c.knots = {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1};
  const CurvatureGraph g = curvature_graph(c, 16);
  ASSERT_EQ(g.t.size(), 4u * 16 + 1);
  for (double k : g.kappa) EXPECT_NEAR(k, 1 / r, 1e-12 / r);
  EXPECT_NEAR(g.kappa_min, 1 / r, 1e-12 / r);
  EXPECT_NEAR(g.kappa_max, 1 / r, 1e-12 / r);
  EXPECT_EQ(g.knots, (std::vector<double>{0.25, 0.5, 0.75}));
  EXPECT_TRUE(std::is_sorted(g.t.begin(), g.t.end()));
}

}  // namespace
}  // namespace pl::test
