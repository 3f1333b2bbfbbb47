// G1 and G2 pairs of degree-5 patches from an auxiliary patch and junction functions,
// checked along the junction against the auxiliary patch and each other.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "classic_test_util.hpp"
#include "core/geometry/differential_geometry.hpp"
#include "core/math/bernstein.hpp"
#include "core/patch/pair_join_patch.hpp"

namespace pl {
namespace {

using test::max_abs;

std::vector<Vec3> aux_points(int du, int dv, unsigned seed) {
  std::vector<Vec3> p;
  const auto noise = test::random_points((du + 1) * (dv + 1), seed, 0.15);
  for (int i = 0; i <= du; ++i)
    for (int j = 0; j <= dv; ++j)
      p.push_back(
          Vec3(double(i) / du, double(j) / dv * 0.6, 0.3 * std::sin(2.0 * i / du) * j / dv) +
          noise[i * (dv + 1) + j]);
  return p;
}

double poly(const std::vector<double>& c, double t) {
  double r = 0;
  for (std::size_t i = 0; i < c.size(); ++i)
    r += c[i] * bernstein(int(c.size()) - 1, int(i), Jet(t)).f;
  return r;
}

Vec3 unit_normal(const SurfaceJet& s) {
  return glm::normalize(glm::cross(s.su, s.sv));
}

double angle_deg(Vec3 a, Vec3 b) {
  return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b)) * 180 / M_PI;
}

// Normal curvature of a surface point in 3D tangent direction d, with normal n.
double normal_curvature(const SurfaceJet& s, Vec3 n, Vec3 d) {
  const double E = glm::dot(s.su, s.su), F = glm::dot(s.su, s.sv), G = glm::dot(s.sv, s.sv);
  const double r1 = glm::dot(d, s.su), r2 = glm::dot(d, s.sv), det = E * G - F * F;
  const double a = (G * r1 - F * r2) / det, b = (E * r2 - F * r1) / det;  // d = a Su + b Sv
  const double L = glm::dot(s.suu, n), M = glm::dot(s.suv, n), N = glm::dot(s.svv, n);
  return (L * a * a + 2 * M * a * b + N * b * b) / (E * a * a + 2 * F * a * b + G * b * b);
}

TEST(ClassicPairJoin, G1PairSharesTheAuxiliaryTangentPlane) {
  JunctionFunctions a{{0.2, -0.1, 0.3, 0.1}, {0.8, 1.0, 1.2}, {}, {}};
  JunctionFunctions b{{-0.1, 0.2, 0.0, 0.1}, {-0.7, -1.1, -0.9}, {}, {}};
  const PairJoinPatch p(1, 3, 1, aux_points(3, 1, 41), a, b);
  const BezierPatch aux = p.auxiliary();
  double angle = 0, gap = 0, formula = 0, angle_aux = 0;
  for (int k = 0; k <= 200; ++k) {
    const double u = k / 200.0;
    const SurfaceJet A = p.final_patch(0).evaluate({u, 0}), B = p.final_patch(1).evaluate({u, 0});
    const SurfaceJet X = aux.evaluate({u, 0});
    gap = std::max({gap, max_abs(A.p - B.p), max_abs(A.p - X.p)});
    angle = std::max(angle,
                     angle_deg(unit_normal(A), -unit_normal(B)));  // B runs away on the other side
    angle_aux = std::max(angle_aux, angle_deg(unit_normal(A), unit_normal(X)));
    formula = std::max({formula, max_abs(A.sv - (poly(a.b1, u) * X.su + poly(a.c1, u) * X.sv)),
                        max_abs(B.sv - (poly(b.b1, u) * X.su + poly(b.c1, u) * X.sv))});
    // The composite patch: continuous normal across v = 1/2.
    const SurfaceJet up = p.evaluate({u, 0.5}), down = p.evaluate({u, std::nextafter(0.5, 0.0)});
    angle = std::max(angle, angle_deg(unit_normal(up), unit_normal(down)));
  }
  std::printf(
      "figure pair_join_g1_max_normal_angle_deg %.3e\nfigure pair_join_g1_gap %.3e\n"
      "figure pair_join_g1_cross_derivative_error %.3e\n",
      angle, gap, formula);
  EXPECT_LT(angle, 1e-6);
  EXPECT_LT(angle_aux, 1e-6);
  EXPECT_LT(gap, 1e-14);
  EXPECT_LT(formula, 1e-13);
  double fd = 0;
  for (const Vec2& x : test::random_domain_points(100, 42))
    fd = std::max(fd, test::fd_mismatch(p, x));
  EXPECT_LT(fd, 1e-6);
  EXPECT_LT(test::interface_mismatch(p, test::random_domain_points(20, 43)), 1e-12);
}

TEST(ClassicPairJoin, G2PairHasTheAuxiliaryNormalCurvatures) {
  JunctionFunctions a{{0.1, -0.2, 0.2}, {0.9, 1.2}, {0.3, 0.0, -0.2, 0.1}, {0.1, -0.3, 0.2}};
  JunctionFunctions b{{-0.2, 0.1, 0.0}, {-1.1, -0.8}, {-0.1, 0.2, 0.1, 0.0}, {0.2, 0.1, -0.1}};
  const PairJoinPatch p(2, 3, 2, aux_points(3, 2, 44), a, b);
  const BezierPatch aux = p.auxiliary();
  double angle = 0, kscale = 0, kdiff = 0, kaux = 0;
  for (int k = 0; k <= 100; ++k) {
    const double u = k / 100.0;
    const SurfaceJet A = p.final_patch(0).evaluate({u, 0}), B = p.final_patch(1).evaluate({u, 0});
    const SurfaceJet X = aux.evaluate({u, 0});
    const Vec3 n = unit_normal(A);
    angle = std::max(angle, angle_deg(n, -unit_normal(B)));
    const Vec3 t1 = glm::normalize(X.su), t2 = glm::cross(n, t1);
    for (int d = 0; d < 12; ++d) {
      const double th = M_PI * d / 12;
      const Vec3 dir = std::cos(th) * t1 + std::sin(th) * t2;
      const double ka = normal_curvature(A, n, dir), kb = normal_curvature(B, n, dir);
      const double kx = normal_curvature(X, n, dir);
      kscale = std::max(kscale, std::fabs(kx));
      kdiff = std::max(kdiff, std::fabs(ka - kb));
      kaux = std::max({kaux, std::fabs(ka - kx), std::fabs(kb - kx)});
    }
  }
  std::printf(
      "figure pair_join_g2_max_normal_angle_deg %.3e\n"
      "figure pair_join_g2_normal_curvature_difference_relative %.3e\n"
      "figure pair_join_g2_vs_auxiliary_relative %.3e\n",
      angle, kdiff / kscale, kaux / kscale);
  EXPECT_LT(angle, 1e-6);
  EXPECT_LT(kdiff / kscale, 1e-6);
  EXPECT_LT(kaux / kscale, 1e-6);
  double fd = 0;
  for (const Vec2& x : test::random_domain_points(100, 45))
    fd = std::max(fd, test::fd_mismatch(p, x));
  EXPECT_LT(fd, 1e-6);
}

TEST(ClassicPairJoin, DraggingAnAuxiliaryPointKeepsTheJoin) {
  JunctionFunctions a{{0.2, -0.1, 0.3, 0.1}, {0.8, 1.0, 1.2}, {}, {}};
  JunctionFunctions b{{-0.1, 0.2, 0.0, 0.1}, {-0.7, -1.1, -0.9}, {}, {}};
  PairJoinPatch p(1, 3, 1, aux_points(3, 1, 46), a, b);
  p.set_control_point(3, p.control_point(3) + Vec3(0.1, 0.3, -0.2));
  double angle = 0;
  for (int k = 0; k <= 50; ++k) {
    const double u = k / 50.0;
    angle = std::max(angle, angle_deg(unit_normal(p.final_patch(0).evaluate({u, 0})),
                                      -unit_normal(p.final_patch(1).evaluate({u, 0}))));
  }
  EXPECT_LT(angle, 1e-6);
}

TEST(ClassicPairJoin, InvalidJunctionsAreRejected) {
  JunctionFunctions ok{{0.2, -0.1, 0.3, 0.1}, {0.8, 1.0, 1.2}, {}, {}};
  JunctionFunctions neg{{0.0}, {-1.0}, {}, {}};
  JunctionFunctions sign_change{{0.0}, {1.0, -1.0}, {}, {}};
  JunctionFunctions too_high{{0.0, 0, 0, 0, 0}, {1.0}, {}, {}};  // b1 p_s of degree 6
  EXPECT_THROW(PairJoinPatch(1, 3, 1, aux_points(3, 1, 1), sign_change, neg),
               std::invalid_argument);
  EXPECT_THROW(PairJoinPatch(1, 3, 1, aux_points(3, 1, 1), ok, ok), std::invalid_argument);
  EXPECT_THROW(PairJoinPatch(1, 3, 1, aux_points(3, 1, 1), too_high, neg), std::invalid_argument);
  EXPECT_THROW(PairJoinPatch(2, 3, 2, aux_points(3, 2, 1), ok, neg),
               std::invalid_argument);  // no b2/c2
}

}  // namespace
}  // namespace pl
