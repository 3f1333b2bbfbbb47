// Principal curvatures against closed forms on exact NURBS surfaces, and consistent with H and K
// at every sample, umbilics included: on a sphere every point is an umbilic, where
// k = H +- sqrt(H^2 - K) kept only half the digits of k_max - k_min.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "classic_test_util.hpp"
#include "core/curve/nurbs_curve.hpp"
#include "core/geometry/differential_geometry.hpp"
#include "core/patch/nurbs_patch.hpp"

namespace pl {
namespace {

// A torus about the z axis through `c`: the tube circle (radius r, centre at distance R from the
// axis) swept around the axis, as the tensor product of two NURBS circles (weights multiply).
NurbsPatch torus(Vec3 c, double R, double r) {
  const NurbsCurve tube = NurbsCurve::circle(Vec3(R, 0, 0), Vec3(1, 0, 0), Vec3(0, 0, 1), r);
  const NurbsCurve ring = NurbsCurve::circle(Vec3(0), Vec3(1, 0, 0), Vec3(0, 1, 0), 1.0);
  std::vector<Vec3> pts;
  std::vector<double> w;
  const std::size_t n = tube.control_points().size(), m = ring.control_points().size();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < m; ++j) {
      const Vec3 t = tube.control_points()[i], g = ring.control_points()[j];
      pts.push_back(c + Vec3(t.x * g.x, t.x * g.y, t.z));
      w.push_back(tube.weights()[i] * ring.weights()[j]);
    }
  return NurbsPatch(2, 2, tube.knots(), ring.knots(), n, m, std::move(pts), std::move(w));
}

// The worst relative disagreement of k_min, k_max with H and K at a sample: their mean against
// H and their product against K, each relative to the curvature's size.
double consistency(const SurfaceGeometry& g) {
  const double k = std::max(std::fabs(g.kmin), std::fabs(g.kmax));
  return std::max(std::fabs((g.kmin + g.kmax) / 2 - g.mean) / k,
                  std::fabs(g.kmin * g.kmax - g.gaussian) / (k * k));
}

TEST(PrincipalCurvature, NurbsSphereEveryPointAnUmbilic) {
  const double R = 1.7;
  const Vec3 c(0.3, -1, 2);
  const NurbsPatch s = NurbsPatch::sphere(c, R);
  double consistent = 0, closed = 0;
  const auto xs = test::random_domain_points(2000, 11, 0.01, 0.99);  // off the poles
  std::vector<SurfaceJet> jets;
  for (const Vec2& x : xs) jets.push_back(s.evaluate(x));
  std::vector<SurfaceGeometry> many(jets.size());
  differential_geometry_many(jets, many);  // the batched (SIMD lane) form
  for (std::size_t i = 0; i < jets.size(); ++i) {
    const SurfaceJet& j = jets[i];
    const SurfaceGeometry g = differential_geometry(j);
    ASSERT_EQ(g.status, GeometryStatus::Regular);
    EXPECT_EQ(many[i].kmin, g.kmin);
    EXPECT_EQ(many[i].kmax, g.kmax);
    consistent = std::max(consistent, consistency(g));
    // Outward normal: the sphere bends away from it, k = -1/R in every direction.
    const double side = glm::dot(g.normal, j.p - c) > 0 ? -1 : 1;
    closed = std::max({closed, std::fabs(g.kmin * R - side), std::fabs(g.kmax * R - side)});
  }
  std::printf("figure nurbs_sphere_principal_consistency %.3e\n", consistent);
  std::printf("figure nurbs_sphere_principal_error %.3e\n", closed);
  EXPECT_LT(consistent, 1e-12);
  EXPECT_LT(closed, 1e-12);
}

TEST(PrincipalCurvature, NurbsTorusAgainstTheClosedForm) {
  const double R = 2.5, r = 0.8;
  const Vec3 c(-1, 0.5, 0.25);
  const NurbsPatch s = torus(c, R, r);
  double consistent = 0, closed = 0;
  for (const Vec2& x : test::random_domain_points(2000, 12)) {
    const SurfaceJet j = s.evaluate(x);
    const SurfaceGeometry g = differential_geometry(j);
    ASSERT_EQ(g.status, GeometryStatus::Regular);
    consistent = std::max(consistent, consistency(g));
    // The tube's centre nearest the point, and the tube angle phi from the outer equator.
    const Vec3 q = j.p - c;
    const double rho = std::hypot(q.x, q.y);
    const Vec3 centre(R * q.x / rho, R * q.y / rho, 0);
    const Vec3 out = (q - centre) / r;
    const double cos_phi = (rho - R) / r;
    // Outward normal: both principal curvatures negative where the surface bends away from it.
    const double side = glm::dot(g.normal, out) > 0 ? -1 : 1;
    double a = side / r, b = side * cos_phi / (R + r * cos_phi);
    if (a > b) std::swap(a, b);
    closed = std::max({closed, std::fabs(g.kmin - a) * r, std::fabs(g.kmax - b) * r});
  }
  std::printf("figure nurbs_torus_principal_consistency %.3e\n", consistent);
  std::printf("figure nurbs_torus_principal_error %.3e\n", closed);
  EXPECT_LT(consistent, 1e-12);
  EXPECT_LT(closed, 1e-12);
}

}  // namespace
}  // namespace pl
