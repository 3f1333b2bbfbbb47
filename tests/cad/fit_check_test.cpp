// Where a surface fit is refined (core/cad/fit_check.hpp): along the direction in which its
// deviation varies, and not at all where a fitted side curve's own error bends it.
#include "core/cad/fit_check.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "cad_test_util.hpp"
#include "core/cad/spline_fit.hpp"

namespace pl {
namespace {

int spans(const std::vector<double>& knots) {
  int n = 0;
  for (std::size_t k = 1; k < knots.size(); ++k) n += knots[k] > knots[k - 1];
  return n;
}

// The sides of f (as fit_surface numbers them), fitted to `position`.
std::array<CadCurve, 4> fitted_sides(const SurfaceFunction& f, double position) {
  std::array<CadCurve, 4> sides;
  for (int s = 0; s < 4; ++s) {
    FitTolerance ct;
    ct.position = position;
    ct.normal_deg = 0.01;
    sides[s] = fit_curve(test::side_curve(f, s), 3, ct).curve;
  }
  return sides;
}

TEST(FitCheck, AMissIsBisectedAlongTheDirectionItsDeviationVaries) {
  // A long strip (4 x 0.1) with a fold across it that rises from its short sides: the surface
  // bends sharply along v, gently along u. The cells are long in u, but the deviation varies
  // along v: bisecting by the cells' size in space split u up to its limit (80 spans against
  // 13 in v) and never reached the tolerance; bisecting along the deviation converges.
  const SurfaceFunction f = [](std::span<const Vec2> uv, std::span<SurfacePoint> out) {
    for (std::size_t k = 0; k < uv.size(); ++k) {
      const double u = uv[k].x, v = uv[k].y;
      const double t = std::tanh(20 * (v - 0.5)), w = std::sin(M_PI * u);
      out[k] = {Vec3(4 * u, 0.1 * v, 0.05 * t * w),
                Vec3(4, 0, 0.05 * t * M_PI * std::cos(M_PI * u)),
                Vec3(0, 0.1, 0.05 * 20 * (1 - t * t) * w)};
    }
  };
  FitTolerance tol;
  tol.position = 1e-5;
  const SurfaceFit fit = fit_surface(f, fitted_sides(f, tol.position / 4), tol);
  ASSERT_TRUE(fit.converged);
  EXPECT_LT(spans(fit.surface.knots_u), spans(fit.surface.knots_v));
}

TEST(FitCheck, AFittedSideThatBendsTheFitEndsItForTheCurveToBeTightened) {
  // A surface that rises steeply from side 0 (it needs short spans there), pinned to sides of
  // which side 0 wiggles by half the tolerance: where that side's own error, taken up across the
  // span next to it, turns the normal past the tolerance, the fit stops (bisecting across the
  // side would double the miss) instead of refining up to its bounds; with the side as fitted it
  // converges.
  const SurfaceFunction f = [](std::span<const Vec2> uv, std::span<SurfacePoint> out) {
    for (std::size_t k = 0; k < uv.size(); ++k) {
      const double u = uv[k].x, v = uv[k].y, e = std::exp(-40 * v);
      out[k] = {Vec3(u, v, 0.1 * std::sin(3 * u) * (1 - e)),
                Vec3(1, 0, 0.3 * std::cos(3 * u) * (1 - e)), Vec3(0, 1, 4 * std::sin(3 * u) * e)};
    }
  };
  FitTolerance tol;
  tol.position = 1e-4;
  const std::array<CadCurve, 4> sides = fitted_sides(f, tol.position / 100);
  std::array<CadCurve, 4> wiggled = sides;
  std::vector<Vec3>& p = wiggled[0].points;
  for (std::size_t i = 1; i + 1 < p.size(); ++i) p[i].z += (i % 2 ? 0.5 : -0.5) * tol.position;
  const SurfaceFit bent = fit_surface(f, wiggled, tol);
  EXPECT_FALSE(bent.converged);
  EXPECT_EQ(bent.end, FitEnd::Curve);
  const SurfaceFit fit = fit_surface(f, sides, tol);
  EXPECT_TRUE(fit.converged);
  EXPECT_LT(bent.work, fit.work);
}

}  // namespace
}  // namespace pl
