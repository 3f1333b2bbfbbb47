// The fairness integrals (core/analysis/surface_energy.hpp) against closed forms: an exact NURBS
// cylinder and sphere (H constant, so ∫|∇H|² dA = 0; ∫(k1² + k2²) dA = 2π h / R and 8π), and a
// bicubic Bézier paraboloid z = (x² + y²) / 2 whose three integrals are computed here by
// Simpson quadrature of the graph's closed-form curvatures.
#include "core/analysis/surface_energy.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/domain/unit_square.hpp"
#include "core/patch/bezier_patch.hpp"
#include "core/patch/nurbs_patch.hpp"

namespace pl {
namespace {

SurfaceIntegrals integrals_at(const Patch& patch, int density) {
  auto tess = std::make_shared<const Tessellation>(patch.domain().tessellate(density));
  const PatchEvaluator ev(patch.clone(), tess);
  return surface_integrals(ev);
}

double rel(double a, double exact) {
  return std::fabs(a - exact) / std::fabs(exact);
}

// The chords of the tessellation cut the curved surface short by O(h²): doubling the density
// must divide the error by about 4 (at least 3.5 here), and the Richardson extrapolation
// (4 I_64 - I_32) / 3, which cancels the h² term, must land on the closed form to `extrapolated`.
void expect_second_order(const char* what, double coarse, double fine, double exact,
                         double extrapolated) {
  const double richardson = (4 * fine - coarse) / 3;
  std::printf("[ %-9s] density 32: %.3e, 64: %.3e relative error (ratio %.2f), extrapolated %.3e\n",
              what, rel(coarse, exact), rel(fine, exact), rel(coarse, exact) / rel(fine, exact),
              rel(richardson, exact));
  EXPECT_GT(rel(coarse, exact) / rel(fine, exact), 3.5) << what;
  EXPECT_LT(rel(richardson, exact), extrapolated) << what;
}

TEST(SurfaceEnergy, CylinderAreaAndBendingConvergeAndMeanCurvatureGradientVanishes) {
  const double r = 2, h = 3;
  const NurbsPatch cylinder = NurbsPatch::cylinder({0.5, -1, 0.25}, r, h);
  const SurfaceIntegrals a = integrals_at(cylinder, 32), b = integrals_at(cylinder, 64);
  expect_second_order("area", a.area, b.area, 2 * M_PI * r * h, 1e-5);
  expect_second_order("bending", a.bending_energy, b.bending_energy, 2 * M_PI * h / r, 1e-5);
  // H = 1/(2R) at every sample up to rounding: its gradient is rounding over the spacing.
  EXPECT_LT(b.mean_curvature_gradient_energy, 1e-20);
}

TEST(SurfaceEnergy, SphereBendingIsEightPiAndMeanCurvatureGradientVanishes) {
  const double r = 1.5;
  const NurbsPatch sphere = NurbsPatch::sphere({0.1, 0.2, -0.3}, r);
  const SurfaceIntegrals a = integrals_at(sphere, 32), b = integrals_at(sphere, 64);
  expect_second_order("area", a.area, b.area, 4 * M_PI * r * r, 1e-5);
  expect_second_order("bending", a.bending_energy, b.bending_energy, 8 * M_PI, 1e-5);
  EXPECT_LT(b.mean_curvature_gradient_energy, 1e-20);
}

// z = (x² + y²) / 2 over [0, 1]²: H = (2 + s) / (2 (1 + s)^{3/2}), K = 1 / (1 + s)², s = x² + y²;
// dA = √(1 + s) dx dy; the surface gradient of the radial H has |∇H|² = |∇_xy H|² / (1 + s).
struct ParaboloidIntegrals {
  double area = 0, bending = 0, gradient = 0;
};
ParaboloidIntegrals paraboloid_exact() {
  // Composite Simpson on a 512 x 512 grid (error O(h⁴) ~ 1e-11 for these smooth integrands: far
  // below the discretization errors checked).
  const int n = 512;
  const auto weight = [n](int i) { return i == 0 || i == n ? 1.0 : i % 2 ? 4.0 : 2.0; };
  ParaboloidIntegrals r;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) {
      const double x = double(i) / n, y = double(j) / n;
      const double ww = weight(i) * weight(j) / (9.0 * n * n);
      const double s = x * x + y * y;
      const double H = (2 + s) / (2 * std::pow(1 + s, 1.5)), K = 1 / ((1 + s) * (1 + s));
      const double dH_ds = -(4 + s) / (4 * std::pow(1 + s, 2.5));
      const double grad_xy2 = 4 * s * dH_ds * dH_ds;  // |2 (x, y) dH/ds|²
      const double dA = std::sqrt(1 + s);
      r.area += ww * dA;
      r.bending += ww * (4 * H * H - 2 * K) * dA;
      r.gradient += ww * grad_xy2 / (1 + s) * dA;
    }
  return r;
}

TEST(SurfaceEnergy, ParaboloidIntegralsMatchTheirClosedForms) {
  // x² on [0, 1] as a cubic in Bernstein form: 0, 0, 1/3, 1.
  const double a[4] = {0, 0, 1.0 / 3, 1};
  std::vector<Vec3> points;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) points.push_back({i / 3.0, j / 3.0, 0.5 * (a[i] + a[j])});
  const BezierPatch paraboloid(3, 3, points);
  const ParaboloidIntegrals exact = paraboloid_exact();
  const SurfaceIntegrals c = integrals_at(paraboloid, 32), f = integrals_at(paraboloid, 64);
  expect_second_order("area", c.area, f.area, exact.area, 1e-5);
  expect_second_order("bending", c.bending_energy, f.bending_energy, exact.bending, 1e-5);
  // The gradient of the linear interpolant is first-order accurate in general; measured here.
  const double ec = rel(c.mean_curvature_gradient_energy, exact.gradient),
               ef = rel(f.mean_curvature_gradient_energy, exact.gradient);
  std::printf("[ grad H   ] exact %.6e; density 32: %.3e, 64: %.3e relative error\n",
              exact.gradient, ec, ef);
  EXPECT_GT(ec / ef, 1.8);
  EXPECT_LT(ef, 1e-2);
}

}  // namespace
}  // namespace pl
