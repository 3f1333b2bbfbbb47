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

TEST(DifferentialGeometry, CurvaturesThatOverflowAreNeverReturned) {
  // Su, Sv the unit axes, Suu = (0, 0, c): K = 0 and H = c / 2 are finite, but H^2 overflows for
  // c = 1e200, so the principal curvatures H -+ sqrt(H^2 - K) would be -inf and +inf. Both the
  // one-sample and the batched path must give finite numbers (here: the sample is Singular), and
  // the same numbers; for c = 1e100 everything is representable and must be exact.
  for (const double c : {1e100, 1e200}) {
    SurfaceJet s;
    s.su = {1, 0, 0}, s.sv = {0, 1, 0}, s.suu = {0, 0, c};
    const SurfaceGeometry one = differential_geometry(s);
    SurfaceJet lanes[5] = {s, s, s, s, s};  // a full block of the batched form and one more
    SurfaceGeometry many[5];
    differential_geometry_many(lanes, many);
    for (const SurfaceGeometry& g : {one, many[0], many[4]}) {
      EXPECT_TRUE(std::isfinite(g.gaussian) && std::isfinite(g.mean) && std::isfinite(g.kmin) &&
                  std::isfinite(g.kmax))
          << c;
      EXPECT_EQ(g.status, one.status) << c;
      EXPECT_EQ(g.kmax, one.kmax) << c;
    }
    if (c == 1e100) {
      EXPECT_EQ(one.status, GeometryStatus::Regular);
      EXPECT_EQ(one.gaussian, 0);
      EXPECT_EQ(one.kmin, 0);
      EXPECT_EQ(one.kmax, c);
    } else {
      EXPECT_EQ(one.status, GeometryStatus::Singular);
    }
  }
}

}  // namespace
}  // namespace pl
