// Tensor-product classic surfaces: interpolating (M_I P M_I^T), Hermite/Ferguson (matrix Q),
// B-spline and NURBS patches, each against an independent computation.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "classic_test_util.hpp"
#include "core/curve/bspline_curve.hpp"
#include "core/domain/tessellation_cache.hpp"
#include "core/eval/patch_evaluator.hpp"
#include "core/geometry/differential_geometry.hpp"
#include "core/patch/bspline_patch.hpp"
#include "core/patch/hermite_patch.hpp"
#include "core/patch/interpolating_patch.hpp"
#include "core/patch/nurbs_patch.hpp"

namespace pl {
namespace {

using test::max_abs;

// Boundary curves against evaluation on the domain sides.
double boundary_mismatch(const Patch& p) {
  const auto curves = p.boundary_curves();
  double worst = 0;
  for (int s = 0; s < 4; ++s)
    for (int k = 0; k <= 20; ++k) {
      const double t = k / 20.0;
      worst =
          std::max(worst, max_abs(curves[s].point(t) - p.evaluate(p.domain().side_point(s, t)).p));
    }
  return worst;
}

TEST(ClassicPatches, InterpolatingSurfacePassesThroughItsGrid) {
  const auto pts = test::random_points(16, 31);
  const InterpolatingPatch p(pts);
  double worst = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      worst = std::max(worst, max_abs(p.evaluate({i / 3.0, j / 3.0}).p - pts[i * 4 + j]));
  const auto xs = test::random_domain_points(40, 5);
  double fd = 0;
  for (const Vec2& x : xs) fd = std::max(fd, test::fd_mismatch(p, x));
  std::printf(
      "figure interpolating_patch_max_point_error %.3e\nfigure interpolating_patch_fd %.3e\n",
      worst, fd);
  EXPECT_LT(worst, 1e-12);
  EXPECT_LT(fd, 1e-6);
  EXPECT_LT(test::interface_mismatch(p, xs), 1e-12);
  EXPECT_LT(boundary_mismatch(p), 1e-12);
}

TEST(ClassicPatches, HermitePatchReproducesCornerData) {
  const auto q = test::random_points(16, 32);
  const HermitePatch p(q);
  double worst = 0;
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) {
      const SurfaceJet s = p.evaluate({double(i), double(j)});
      worst = std::max({worst, max_abs(s.p - p.r(i, j)), max_abs(s.su - p.ru(i, j)),
                        max_abs(s.sv - p.rv(i, j)), max_abs(s.suv - p.ruv(i, j))});
    }
  const auto xs = test::random_domain_points(40, 6);
  double fd = 0;
  for (const Vec2& x : xs) fd = std::max(fd, test::fd_mismatch(p, x));
  std::printf("figure hermite_patch_corner_error %.3e\nfigure hermite_patch_fd %.3e\n", worst, fd);
  EXPECT_LT(worst, 1e-12);
  EXPECT_LT(fd, 1e-6);
  EXPECT_LT(test::interface_mismatch(p, xs), 1e-12);
  EXPECT_LT(boundary_mismatch(p), 1e-12);
}

TEST(ClassicPatches, BSplinePatchAgreesWithDeBoorAndKnotInsertion) {
  const std::vector<double> U = {0, 0, 0, 0, 0.2, 0.25, 0.6, 1, 1, 1, 1};  // cubic, non-uniform
  const std::vector<double> V = {-1, -1, -1, 0.5, 0.5, 2, 3, 3, 3};        // quadratic, double knot
  const std::size_t nu = 7, nv = 6;
  const BSplinePatch p(3, 2, U, V, nu, nv, test::random_points(nu * nv, 33));
  std::vector<glm::dvec4> hom;
  for (const Vec3& c : p.control_points()) hom.emplace_back(c, 1.0);
  const BSplinePatch refined = p.inserted_u(0.41).inserted_v(1.3).inserted_v(2.5);
  const auto xs = test::random_domain_points(300, 7);
  double deboor = 0, insert = 0, fd = 0;
  for (const Vec2& x : xs) {
    const SurfaceJet s = p.evaluate(x);
    const Vec3 ref(
        test::de_boor_surface(3, 2, U, V, nu, nv, hom, p.grid().u_of(x.x), p.grid().v_of(x.y)));
    deboor = std::max(deboor, max_abs(s.p - ref));
    const SurfaceJet r = refined.evaluate(x);
    insert = std::max(
        {insert, max_abs(s.p - r.p), 1e-2 * max_abs(s.su - r.su), 1e-2 * max_abs(s.sv - r.sv)});
    fd = std::max(fd, test::fd_mismatch(p, x));
  }
  std::printf(
      "figure bspline_patch_vs_de_boor %.3e\nfigure bspline_patch_knot_insertion_change %.3e\n"
      "figure bspline_patch_fd %.3e\n",
      deboor, insert, fd);
  EXPECT_LT(deboor, 1e-13);
  EXPECT_LT(insert, 1e-12);
  EXPECT_LT(fd, 1e-5);
  EXPECT_LT(test::interface_mismatch(p, std::vector<Vec2>(xs.begin(), xs.begin() + 30)), 1e-12);
}

TEST(ClassicPatches, MultiSpanUnclampedSidesAreExactBoundaryPoints) {
  // Unclamped, non-uniform knots in both directions: no side is a row of control points, and
  // every side has several spans. boundary_point (curve classes) against homogeneous de Boor at
  // the side's (u, v), for a B-spline and a NURBS with unequal weights.
  const std::vector<double> U = {-0.5, -0.2, 0, 0.1, 0.2, 0.25, 0.6, 1, 1.3, 1.4, 2};  // cubic
  const std::vector<double> V = {-1, -0.6, -0.1, 0.5, 0.5, 2, 3, 3.5, 4};              // quadratic
  const std::size_t nu = 7, nv = 6;
  const auto pts = test::random_points(nu * nv, 34);
  std::vector<double> w;
  for (std::size_t k = 0; k < nu * nv; ++k) w.push_back(0.5 + 0.1 * double((k * 7) % 11));
  const BSplinePatch b(3, 2, U, V, nu, nv, pts);
  const NurbsPatch n(3, 2, U, V, nu, nv, pts, w);
  std::vector<glm::dvec4> hb, hn;
  for (std::size_t k = 0; k < pts.size(); ++k)
    hb.emplace_back(pts[k], 1.0), hn.emplace_back(w[k] * pts[k], w[k]);
  double worst_b = 0, worst_n = 0, polygon_b = 0;
  for (int side = 0; side < 4; ++side)
    for (int k = 0; k <= 40; ++k) {
      const double t = k / 40.0;
      const Vec2 x = b.domain().side_point(side, t);
      const double u = b.grid().u_of(x.x), v = b.grid().v_of(x.y);
      const Vec3 rb(test::de_boor_surface(3, 2, U, V, nu, nv, hb, u, v));
      const glm::dvec4 h = test::de_boor_surface(3, 2, U, V, nu, nv, hn, u, v);
      worst_b = std::max(worst_b, max_abs(b.boundary_point(side, t) - rb));
      worst_n = std::max(worst_n, max_abs(n.boundary_point(side, t) - Vec3(h) / h.w));
      polygon_b = std::max(polygon_b, max_abs(b.boundary_curves()[side].point(t) - rb));
    }
  std::printf(
      "figure bspline_unclamped_boundary_point_vs_de_boor %.3e\n"
      "figure nurbs_unclamped_boundary_point_vs_de_boor %.3e\n"
      "figure bspline_unclamped_control_polygon_bezier_deviation %.3e\n",
      worst_b, worst_n, polygon_b);
  EXPECT_LT(worst_b, 1e-13);
  EXPECT_LT(worst_n, 1e-13);
  EXPECT_GT(polygon_b, 1e-3);  // the single-Bézier fallback is really not the side here
}

TEST(ClassicPatches, BSplineDragTouchesOnlyTheSupport) {
  const std::size_t n = 12;
  const BSplinePatch p(3, 3, BSplineCurve::clamped_uniform_knots(3, n),
                       BSplineCurve::clamped_uniform_knots(3, n), n, n,
                       test::random_points(n * n, 34));
  TessellationCache cache;
  PatchEvaluator ev(p.clone(), cache.get(p.domain(), 64));
  const std::size_t k = 5 * n + 6;
  const std::size_t touched = ev.move_control_point(k, p.control_point(k) + Vec3(0.1, -0.2, 0.3));
  auto moved = p.clone();
  moved->set_control_point(k, p.control_point(k) + Vec3(0.1, -0.2, 0.3));
  PatchEvaluator ref(std::move(moved), cache.get(p.domain(), 64));
  double worst = 0;
  for (std::size_t i = 0; i < ev.sample_count(); ++i)
    worst = std::max(worst, max_abs(ev.jets()[i].p - ref.jets()[i].p));
  std::printf("figure bspline_drag_samples_touched %zu of %zu\n", touched, ev.sample_count());
  EXPECT_LT(touched * 2, ev.sample_count());  // stored as a sparse column
  EXPECT_LT(worst, 1e-13);
}

TEST(ClassicPatches, NurbsSphereIsExact) {
  const double R = 1.7;
  const Vec3 c(0.3, -1, 2);
  const NurbsPatch s = NurbsPatch::sphere(c, R);
  const NurbsPatch refined = s.inserted_u(0.3);
  std::vector<glm::dvec4> hom;
  for (std::size_t k = 0; k < s.size(); ++k)
    hom.emplace_back(s.weights()[k] * s.control_point(k), s.weights()[k]);
  double radius = 0, gauss = 0, mean = 0, principal = 0, fd = 0, deboor = 0, insert = 0;
  const auto xs = test::random_domain_points(500, 8, 0.01, 0.99);  // away from the pole rows
  for (const Vec2& x : xs) {
    const SurfaceJet j = s.evaluate(x);
    const SurfaceGeometry g = differential_geometry(j);
    ASSERT_EQ(g.status, GeometryStatus::Regular);
    radius = std::max(radius, std::fabs(glm::length(j.p - c) - R));
    gauss = std::max(gauss, std::fabs(g.gaussian - 1 / (R * R)));
    mean = std::max(mean, std::fabs(std::fabs(g.mean) - 1 / R));
    // Normal curvature II(d)/I(d) in random tangent directions: every direction bends by 1/R.
    const FundamentalForms f = fundamental_forms(j);
    for (int d = 0; d < 8; ++d) {
      const double a = std::cos(0.7 * d + x.x), b = std::sin(0.7 * d + x.y);
      const double kn = (f.L * a * a + 2 * f.M * a * b + f.N * b * b) /
                        (f.E * a * a + 2 * f.F * a * b + f.G * b * b);
      principal = std::max(principal, std::fabs(std::fabs(kn) - 1 / R));
    }
    fd = std::max(fd, test::fd_mismatch(s, x));
    const glm::dvec4 h = test::de_boor_surface(2, 2, s.grid().knots_u(), s.grid().knots_v(), 5, 9,
                                               hom, s.grid().u_of(x.x), s.grid().v_of(x.y));
    deboor = std::max(deboor, max_abs(j.p - Vec3(h) / h.w));
    insert = std::max(insert, max_abs(j.p - refined.evaluate(x).p));
  }
  std::printf(
      "figure nurbs_sphere_radius_error %.3e\nfigure nurbs_sphere_K_error %.3e\n"
      "figure nurbs_sphere_H_error %.3e\nfigure nurbs_sphere_normal_curvature_error %.3e\n"
      "figure nurbs_sphere_fd %.3e\nfigure nurbs_sphere_vs_de_boor %.3e\n"
      "figure nurbs_sphere_knot_insertion_change %.3e\n",
      radius, gauss, mean, principal, fd, deboor, insert);
  EXPECT_LT(radius, 1e-10);
  EXPECT_LT(gauss, 1e-10);
  EXPECT_LT(mean, 1e-10);
  EXPECT_LT(principal, 1e-10);
  EXPECT_LT(fd, 1e-5);
  EXPECT_LT(deboor, 1e-13);
  EXPECT_LT(insert, 1e-13);
  EXPECT_LT(test::interface_mismatch(s, std::vector<Vec2>(xs.begin(), xs.begin() + 20)), 1e-11);
}

TEST(ClassicPatches, NurbsCylinderIsExact) {
  const double R = 0.8;
  const NurbsPatch s = NurbsPatch::cylinder(Vec3(1, 2, -1), R, 3);
  double radius = 0, principal = 0, gauss = 0, fd = 0;
  for (const Vec2& x : test::random_domain_points(500, 9)) {
    const SurfaceJet j = s.evaluate(x);
    const SurfaceGeometry g = differential_geometry(j);
    radius = std::max(radius, std::fabs(glm::length(Vec2(j.p.x - 1, j.p.y - 2)) - R));
    principal =
        std::max(principal, std::fabs(std::max(std::fabs(g.kmin), std::fabs(g.kmax)) - 1 / R));
    gauss = std::max(gauss, std::fabs(g.gaussian));
    fd = std::max(fd, test::fd_mismatch(s, x));
  }
  std::printf(
      "figure nurbs_cylinder_radius_error %.3e\nfigure nurbs_cylinder_curvature_error %.3e\n"
      "figure nurbs_cylinder_K %.3e\nfigure nurbs_cylinder_fd %.3e\n",
      radius, principal, gauss, fd);
  EXPECT_LT(radius, 1e-10);
  EXPECT_LT(principal, 1e-10);
  EXPECT_LT(gauss, 1e-10);
  EXPECT_LT(fd, 1e-5);
}

TEST(ClassicPatches, InvalidInputIsRejected) {
  EXPECT_THROW(InterpolatingPatch(test::random_points(15, 1)), std::invalid_argument);
  EXPECT_THROW(HermitePatch(test::random_points(17, 1)), std::invalid_argument);
  EXPECT_THROW(BSplinePatch(3, 3, {0, 0, 0, 0, 1, 1, 1, 1}, {0, 0, 0, 0, 1, 1, 1, 1}, 4, 4,
                            test::random_points(15, 1)),
               std::invalid_argument);
  EXPECT_THROW(
      NurbsPatch(1, 1, {0, 0, 1, 1}, {0, 0, 1, 1}, 2, 2, test::random_points(4, 1), {1, 1, -1, 1}),
      std::invalid_argument);
}

}  // namespace
}  // namespace pl
