// Curvature from exact derivatives against closed forms.
#include "core/geometry/differential_geometry.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/patch/bezier_patch.hpp"

namespace pl {
namespace {

// z = x y over [-1,1]^2 as a bilinear Bézier patch: S(u,v) = (2u-1, 2v-1, (2u-1)(2v-1)).
BezierPatch saddle() {
  return BezierPatch(1, 1, {{-1, -1, 1}, {-1, 1, -1}, {1, -1, -1}, {1, 1, 1}});
}

TEST(DifferentialGeometry, SaddleZEqualsXYMatchesAnalyticCurvature) {
  const BezierPatch p = saddle();
  for (double u = 0; u <= 1.0001; u += 0.125)
    for (double v = 0; v <= 1.0001; v += 0.125) {
      const double x = 2 * u - 1, y = 2 * v - 1;
      const SurfaceGeometry g = differential_geometry(p.evaluate({u, v}));
      ASSERT_EQ(g.status, GeometryStatus::Regular);
      // Graph z = f(x,y) with upward normal: K = (f_xx f_yy - f_xy^2)/W^4, H = ... / (2 W^3).
      const double W2 = 1 + x * x + y * y;
      const double K = -1 / (W2 * W2);
      const double H = -x * y / std::pow(W2, 1.5);
      EXPECT_NEAR(g.gaussian, K, 1e-12) << x << "," << y;
      EXPECT_NEAR(g.mean, H, 1e-12) << x << "," << y;
      EXPECT_NEAR(g.kmin * g.kmax, K, 1e-12);
      EXPECT_NEAR(0.5 * (g.kmin + g.kmax), H, 1e-12);
      const Vec3 n = glm::normalize(Vec3(-y, -x, 1));
      EXPECT_NEAR(glm::length(g.normal - n), 0, 1e-14);
    }
}

TEST(DifferentialGeometry, PrincipalDirectionsDiagonaliseTheShapeOperator) {
  const BezierPatch p = saddle();
  const SurfaceJet s = p.evaluate({0.5, 0.5});  // origin: principal directions are (1,±1,0)/√2
  const PrincipalDirections d = principal_directions(s);
  const SurfaceGeometry g = differential_geometry(s);
  EXPECT_NEAR(g.kmin, -1, 1e-12);
  EXPECT_NEAR(g.kmax, 1, 1e-12);
  EXPECT_NEAR(std::fabs(glm::dot(d.dir_min, glm::normalize(Vec3(1, -1, 0)))), 1, 1e-12);
  EXPECT_NEAR(std::fabs(glm::dot(d.dir_max, glm::normalize(Vec3(1, 1, 0)))), 1, 1e-12);
}

TEST(DifferentialGeometry, DegenerateParameterisationIsSingularNotNaN) {
  // All of side u = 0 collapses to one point: Sv = 0 there.
  const BezierPatch p(1, 1, {{0, 0, 0}, {0, 0, 0}, {1, 0, 0}, {1, 1, 0}});
  const SurfaceGeometry g = differential_geometry(p.evaluate({0, 0.5}));
  EXPECT_EQ(g.status, GeometryStatus::Singular);
  EXPECT_TRUE(std::isfinite(g.gaussian) && std::isfinite(g.mean));
  EXPECT_TRUE(std::isfinite(g.normal.x));
}

}  // namespace
}  // namespace pl
