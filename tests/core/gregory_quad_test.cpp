#include "core/patch/gregory_quad.hpp"

#include <gtest/gtest.h>

#include "core/base/data_error.hpp"
#include "core/io/scene_io.hpp"
#include "core/patch/bezier_patch.hpp"
#include "gregory_test_util.hpp"

namespace pl {
namespace {

using Q = GregoryQuadPatch;

// Grid position (i, j) of boundary point b, written out from the header's diagram.
constexpr int kBoundaryGrid[12][2] = {{0, 0}, {1, 0}, {2, 0}, {3, 0}, {3, 1}, {3, 2},
                                      {3, 3}, {2, 3}, {1, 3}, {0, 3}, {0, 2}, {0, 1}};
// Grid position of twin 12 + t.
constexpr int kTwinGrid[8][2] = {{1, 1}, {2, 1}, {2, 1}, {2, 2}, {2, 2}, {1, 2}, {1, 2}, {1, 1}};

// The Gregory points of a bicubic grid P[i][j] with both twins at the grid point.
std::vector<Vec3> gregory_points(const std::vector<Vec3>& grid) {  // grid[i*4+j]
  std::vector<Vec3> g(Q::kPointCount);
  for (int b = 0; b < 12; ++b) g[b] = grid[kBoundaryGrid[b][0] * 4 + kBoundaryGrid[b][1]];
  for (int t = 0; t < 8; ++t) g[12 + t] = grid[kTwinGrid[t][0] * 4 + kTwinGrid[t][1]];
  return g;
}

Q random_gregory(unsigned seed) {
  return Q(test::random_points(Q::kPointCount, seed));
}

std::vector<Vec2> test_points() {
  std::vector<Vec2> xs;
  for (double u : {0.0, 1e-9, 0.13, 0.5, 0.77, 1 - 1e-9, 1.0})
    for (double v : {0.0, 1e-9, 0.31, 0.5, 0.92, 1 - 1e-9, 1.0}) xs.emplace_back(u, v);
  return xs;
}

TEST(GregoryQuad, CoincidingTwinsGiveTheBicubicBezierPatch) {
  const auto grid = test::random_points(16, 3);
  const BezierPatch bezier(3, 3, grid);
  const Q gregory(gregory_points(grid));
  for (Vec2 x : test_points())
    EXPECT_LT(test::jet_distance(gregory.evaluate(x), bezier.evaluate(x)), 1e-12)
        << x.x << " " << x.y;
}

TEST(GregoryQuad, FiniteEverywhereIncludingCornersEdgesAndCentre) {
  const Q p = random_gregory(7);
  for (Vec2 x : test_points()) EXPECT_TRUE(test::finite_jet(p.evaluate(x))) << x.x << " " << x.y;
  const Tessellation t = p.domain().tessellate(16);
  for (Vec2 x : t.points) EXPECT_TRUE(test::finite_jet(p.evaluate(x)));
}

TEST(GregoryQuad, BasisIsAPartitionOfUnity) {
  const Q p = random_gregory(8);
  for (Vec2 x : test_points()) test::expect_partition_of_unity(p, x);
}

TEST(GregoryQuad, DerivativesMatchFiniteDifferencesAwayFromCorners) {
  const Q p = random_gregory(9);
  for (Vec2 x : {Vec2(0.3, 0.4), Vec2(0.05, 0.6), Vec2(0.8, 0.1), Vec2(0.5, 0.5), Vec2(0.9, 0.95)})
    test::expect_matches_finite_differences(p, x);
}

// Each side interpolates its boundary cubic, and its cross-boundary derivative is the cubic
// 3 (second row - boundary) of that side's own twins only: the Gregory property.
TEST(GregoryQuad, SidesAndCrossDerivativesDependOnlyOnTheirOwnTwins) {
  const Q p = random_gregory(10);
  const auto& c = p.control_points();
  const auto curves = p.boundary_curves();
  // Second row of side s, from its start: row end, twin 0, twin 1, row end (boundary points of
  // the neighbouring sides).
  for (int s = 0; s < 4; ++s) {
    const std::vector<Vec3> row{c[Q::boundary_index(s + 3, 2)], c[Q::twin_index(s, 0)],
                                c[Q::twin_index(s, 1)], c[Q::boundary_index(s + 1, 1)]};
    std::vector<Vec3> cross;
    for (int j = 0; j < 4; ++j) cross.push_back(3.0 * (row[j] - c[Q::boundary_index(s, j)]));
    const BezierCurve cross_curve(cross);
    for (double t : {0.0, 0.2, 0.5, 0.81, 1.0}) {
      const Vec2 x = p.domain().side_point(s, t);
      const SurfaceJet j = p.evaluate(x);
      EXPECT_LT(test::max_abs(j.p - curves[s].point(t)), 1e-14);
      // Inward derivative of side s: +v, -u, -v, +u.
      const Vec3 inward = s == 0 ? j.sv : s == 1 ? -j.su : s == 2 ? -j.sv : j.su;
      EXPECT_LT(test::max_abs(inward - cross_curve.point(t)), 1e-13) << s << " " << t;
    }
  }
}

// At a corner value and first derivatives are the limits; second derivatives along the sides
// are the boundary curves'. Approaching the corner, position and first derivatives converge.
TEST(GregoryQuad, CornersTakeTheLimits) {
  const Q p = random_gregory(11);
  const auto curves = p.boundary_curves();
  for (int s = 0; s < 4; ++s) {
    const Vec2 corner = p.domain().side_point(s, 0);
    const SurfaceJet j = p.evaluate(corner);
    const auto along = curves[s].derivative(), back = curves[(s + 3) % 4].derivative();
    const Vec2 du = p.domain().side_point(s, 1) - corner;  // side direction in the domain
    const Vec3 d_side = du.x * j.su + du.y * j.sv;
    EXPECT_LT(test::max_abs(d_side - along.point(0)), 1e-13);
    // Second derivative along the side: the boundary curve's (the guarded twist does not
    // enter it).
    const Vec3 dd = du.x * du.x * j.suu + 2 * du.x * du.y * j.suv + du.y * du.y * j.svv;
    EXPECT_LT(test::max_abs(dd - along.derivative().point(0)), 1e-12);
    const Vec2 dv = p.domain().side_point((s + 3) % 4, 0) - corner;  // back along side s-1
    EXPECT_LT(test::max_abs(dv.x * j.su + dv.y * j.sv + back.point(1)), 1e-13);
    for (double eps : {1e-4, 1e-7}) {
      const Vec2 x = corner + eps * (p.domain().interior_point() - corner);
      const SurfaceJet n = p.evaluate(x);
      EXPECT_LT(test::max_abs(n.p - j.p), 1e2 * eps);
      EXPECT_LT(test::max_abs(n.su - j.su), 1e2 * eps);
      EXPECT_LT(test::max_abs(n.sv - j.sv), 1e2 * eps);
    }
  }
}

TEST(GregoryQuad, KindsAndSizeChecks) {
  const Q p = random_gregory(12);
  for (std::size_t k = 0; k < 12; ++k) EXPECT_EQ(p.kind(k), ControlPointKind::Boundary);
  for (std::size_t k = 12; k < 20; ++k) EXPECT_EQ(p.kind(k), ControlPointKind::Twin);
  EXPECT_THROW(Q(test::random_points(16, 1)), std::invalid_argument);
}

TEST(GregoryQuad, SceneRoundTripKeepsEveryPoint) {
  Scene s;
  s.patches.push_back({"g", std::make_shared<Q>(random_gregory(13))});
  const Scene back = parse_scene(scene_to_json(s), "mem");
  ASSERT_EQ(back.patches.size(), 1u);
  EXPECT_EQ(back.patches[0].patch->type(), "gregory-quad");
  EXPECT_EQ(back.patches[0].patch->control_points(), s.patches[0].patch->control_points());
  EXPECT_THROW(parse_scene(R"({"patchlab": 1, "patches": [{"type": "gregory-quad",
      "points": [[0,0,0]]}]})",
                           "mem"),
               DataError);
}

}  // namespace
}  // namespace pl
