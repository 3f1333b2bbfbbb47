// G1 gap filling between two bicubic B-spline patches with cross-boundary derivatives rescaled
// by d(v) / |q_u(v)|.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "classic_test_util.hpp"
#include "core/patch/gap_fill_patch.hpp"

namespace pl {
namespace {

using test::max_abs;

BSplinePatch make_q() {
  const std::size_t nu = 6, nv = 5;
  std::vector<Vec3> p;
  for (std::size_t i = 0; i < nu; ++i)
    for (std::size_t j = 0; j < nv; ++j) {
      const double x = 0.2 * i, y = 0.5 * j;
      p.push_back({x, y, 0.2 * std::sin(2 * x + y) + 0.05 * x * y});
    }
  return BSplinePatch(3, 3, BSplineCurve::clamped_uniform_knots(3, nu),
                      {0, 0, 0, 0, 0.8, 2, 2, 2, 2}, nu, nv, p);
}

BSplinePatch make_r() {
  const std::size_t nu = 5, nv = 6;
  std::vector<Vec3> p;
  for (std::size_t i = 0; i < nu; ++i)
    for (std::size_t j = 0; j < nv; ++j) {
      const double y = 0.4 * j, x = 1.3 + 0.25 * y + 0.2 * i;  // the gap widens with v
      p.push_back({x, y, 0.3 - 0.15 * std::cos(x - y) + 0.1 * i * i * 0.2});
    }
  return BSplinePatch(3, 3, {0, 0, 0, 0, 0.5, 1, 1, 1, 1}, {0, 0, 0, 0, 0.5, 1.1, 2, 2, 2, 2}, nu,
                      nv, p);
}

double angle_deg(const SurfaceJet& a, const SurfaceJet& b) {
  const Vec3 na = glm::normalize(glm::cross(a.su, a.sv)),
             nb = glm::normalize(glm::cross(b.su, b.sv));
  return std::atan2(glm::length(glm::cross(na, nb)), glm::dot(na, nb)) * 180 / M_PI;
}

struct Junctions {
  double angle = 0, gap = 0, width = 0;
};
Junctions junctions(const GapFillPatch& g) {
  Junctions r;
  for (int k = 0; k <= 300; ++k) {
    const double y = k / 300.0;
    const SurfaceJet q = g.piece_jet(0, {1, y}), s0 = g.piece_jet(1, {0, y});
    const SurfaceJet s1 = g.piece_jet(1, {1, y}), rr = g.piece_jet(2, {0, y});
    r.angle = std::max({r.angle, angle_deg(q, s0), angle_deg(s1, rr)});
    r.gap = std::max({r.gap, max_abs(q.p - s0.p), max_abs(s1.p - rr.p)});
    const double d = glm::length(q.p - rr.p);
    r.width = std::max(
        {r.width, std::fabs(glm::length(s0.su) - d) / d, std::fabs(glm::length(s1.su) - d) / d});
  }
  return r;
}

TEST(ClassicGapFill, FillIsG1WithBothPatchesAndScaledToTheGapWidth) {
  const GapFillPatch g(make_q(), make_r());
  const Junctions j = junctions(g);
  std::printf(
      "figure gap_fill_max_normal_angle_deg %.3e\nfigure gap_fill_position_gap %.3e\n"
      "figure gap_fill_cross_derivative_length_vs_width_relative %.3e\n",
      j.angle, j.gap, j.width);
  EXPECT_LT(j.angle, 1e-6);
  EXPECT_LT(j.gap, 1e-14);
  EXPECT_LT(j.width, 1e-12);
  double fd = 0;
  for (const Vec2& x : test::random_domain_points(300, 51))
    fd = std::max(fd, test::fd_mismatch(g, x, 1e-6));
  std::printf("figure gap_fill_fd %.3e\n", fd);
  EXPECT_LT(fd, 1e-5);
  EXPECT_LT(test::interface_mismatch(g, test::random_domain_points(10, 52)), 1e-11);
}

TEST(ClassicGapFill, DraggingAPointNearTheGapKeepsG1) {
  GapFillPatch g(make_q(), make_r());
  const std::size_t k = 4 * 5 + 2;  // q's second-to-last row: changes q_u along the junction
  g.set_control_point(k, g.control_point(k) + Vec3(0.05, 0.1, 0.2));
  const std::size_t kr = g.q().size() + 6 + 3;  // r's second row
  g.set_control_point(kr, g.control_point(kr) + Vec3(-0.1, 0.0, 0.15));
  const Junctions j = junctions(g);
  std::printf("figure gap_fill_after_drag_max_normal_angle_deg %.3e\n", j.angle);
  EXPECT_LT(j.angle, 1e-6);
  EXPECT_LT(j.gap, 1e-14);
}

TEST(ClassicGapFill, ClosingGapIsRejected) {
  BSplinePatch q = make_q();
  const BSplinePatch r = make_r();
  // Move q's end row onto r's start curve at v = a: the gap width vanishes there.
  EXPECT_THROW(
      {
        std::vector<Vec3> p = q.control_points();
        p[5 * 5] = r.control_point(0);
        GapFillPatch(BSplinePatch(3, 3, q.grid().knots_u(), q.grid().knots_v(), 6, 5, p), r);
      },
      std::invalid_argument);
  EXPECT_THROW(GapFillPatch(q, BSplinePatch(3, 3, {0, 0, 0, 0, 0.5, 1, 1, 1, 1},
                                            BSplineCurve::clamped_uniform_knots(3, 6), 5, 6,
                                            r.control_points())),
               std::invalid_argument);  // v range [0,1] differs from [0,2]
}

}  // namespace
}  // namespace pl
