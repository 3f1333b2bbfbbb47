#include "core/patch/gregory_tri.hpp"

#include <gtest/gtest.h>

#include <array>

#include "core/io/scene_io.hpp"
#include "gregory_test_util.hpp"

namespace pl {
namespace {

using T = GregoryTriPatch;

// An independent quartic Bézier triangle: control points b[i][j] with exponents (i, j, 4-i-j)
// of (a, b, c) = (1-u-v, u, v), evaluated by the blossom (de Casteljau with one barycentric
// argument per step). D_d S = 4 blossom(x, x, x, d), D_d D_e S = 12 blossom(x, x, d, e), with
// d_u = (-1, 1, 0) and d_v = (-1, 0, 1) the barycentric directions of u and v.
struct QuarticTriangle {
  std::array<std::array<Vec3, 5>, 5> b;  // b[i][j], i + j <= 4 (k = 4 - i - j)

  Vec3 blossom(std::array<std::array<double, 3>, 4> args) const {
    auto net = b;
    for (int level = 4; level > 0; --level) {
      const auto& w = args[4 - level];
      for (int i = 0; i < level; ++i)
        for (int j = 0; i + j < level; ++j)
          net[i][j] = w[0] * net[i + 1][j] + w[1] * net[i][j + 1] + w[2] * net[i][j];
    }
    return net[0][0];
  }
  SurfaceJet evaluate(Vec2 x) const {
    const std::array<double, 3> p{1 - x.x - x.y, x.x, x.y}, du{-1, 1, 0}, dv{-1, 0, 1};
    SurfaceJet s;
    s.p = blossom({p, p, p, p});
    s.su = 4.0 * blossom({p, p, p, du});
    s.sv = 4.0 * blossom({p, p, p, dv});
    s.suu = 12.0 * blossom({p, p, du, du});
    s.suv = 12.0 * blossom({p, p, du, dv});
    s.svv = 12.0 * blossom({p, p, dv, dv});
    return s;
  }
};

// Exponents (i, j, k) of (a, b, c) of boundary point s, j per the header's diagram.
std::array<int, 3> boundary_exponents(int side, int j) {
  if (side == 0) return {4 - j, j, 0};
  if (side == 1) return {0, 4 - j, j};
  return {j, 0, 4 - j};
}
constexpr int kTwinExponents[6][3] = {{2, 1, 1}, {1, 2, 1}, {1, 2, 1},
                                      {1, 1, 2}, {1, 1, 2}, {2, 1, 1}};

std::vector<Vec3> gregory_points(const QuarticTriangle& q) {
  std::vector<Vec3> g(T::kPointCount);
  for (int s = 0; s < 3; ++s)
    for (int j = 0; j < 4; ++j) {
      const auto e = boundary_exponents(s, j);
      g[T::boundary_index(s, j)] = q.b[e[0]][e[1]];
    }
  for (int t = 0; t < 6; ++t) g[12 + t] = q.b[kTwinExponents[t][0]][kTwinExponents[t][1]];
  return g;
}

QuarticTriangle random_triangle(unsigned seed) {
  const auto pts = test::random_points(25, seed);
  QuarticTriangle q;
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j) q.b[i][j] = pts[i * 5 + j];
  return q;
}

std::vector<Vec2> test_points() {
  std::vector<Vec2> xs;
  for (double u : {0.0, 1e-9, 0.13, 1.0 / 3, 0.5, 0.77, 1 - 1e-9, 1.0})
    for (double v : {0.0, 1e-9, 0.2, 1.0 / 3, 0.5, 0.92, 1.0})
      if (u + v <= 1) xs.emplace_back(u, v);
  xs.emplace_back(0.3, 0.7);
  xs.emplace_back(0.5, 0.5);
  return xs;
}

TEST(GregoryTri, IndependentQuarticEvaluatorIsAPolynomialOfTheRightCorners) {
  const QuarticTriangle q = random_triangle(1);
  // Corners A, B, C are b[4][0], b[0][4], b[0][0].
  EXPECT_LT(test::max_abs(q.evaluate({0, 0}).p - q.b[4][0]), 1e-15);
  EXPECT_LT(test::max_abs(q.evaluate({1, 0}).p - q.b[0][4]), 1e-15);
  EXPECT_LT(test::max_abs(q.evaluate({0, 1}).p - q.b[0][0]), 1e-15);
}

TEST(GregoryTri, CoincidingTwinsGiveTheQuarticBezierTriangle) {
  const QuarticTriangle q = random_triangle(2);
  const T gregory(gregory_points(q));
  for (Vec2 x : test_points())
    EXPECT_LT(test::jet_distance(gregory.evaluate(x), q.evaluate(x)), 1e-12) << x.x << " " << x.y;
}

TEST(GregoryTri, FiniteEverywhereIncludingCornersEdgesAndCentre) {
  const T p(test::random_points(T::kPointCount, 3));
  for (Vec2 x : test_points()) EXPECT_TRUE(test::finite_jet(p.evaluate(x))) << x.x << " " << x.y;
  for (Vec2 x : p.domain().tessellate(16).points) EXPECT_TRUE(test::finite_jet(p.evaluate(x)));
}

TEST(GregoryTri, BasisIsAPartitionOfUnity) {
  const T p(test::random_points(T::kPointCount, 4));
  for (Vec2 x : test_points()) test::expect_partition_of_unity(p, x);
}

TEST(GregoryTri, DerivativesMatchFiniteDifferencesAwayFromCorners) {
  const T p(test::random_points(T::kPointCount, 5));
  for (Vec2 x :
       {Vec2(0.2, 0.3), Vec2(0.05, 0.6), Vec2(0.7, 0.1), Vec2(1.0 / 3, 1.0 / 3), Vec2(0.45, 0.45)})
    test::expect_matches_finite_differences(p, x);
}

// On side s the patch is the side's quartic and its derivative towards the opposite corner is
// 4 (row 1 - boundary) with row 1 made of that side's own twins (and the neighbouring sides'
// boundary points at the ends).
TEST(GregoryTri, SidesAndCrossDerivativesDependOnlyOnTheirOwnTwins) {
  const T p(test::random_points(T::kPointCount, 6));
  const auto& c = p.control_points();
  const auto curves = p.boundary_curves();
  const Vec2 opposite[3] = {{0, 1}, {0, 0}, {1, 0}};  // C, A, B
  for (int s = 0; s < 3; ++s) {
    // Row 1 of side s from its start: previous side's point 3, twins, next side's point 1.
    const std::vector<Vec3> row{c[T::boundary_index(s + 2, 3)], c[T::twin_index(s, 0)],
                                c[T::twin_index(s, 1)], c[T::boundary_index(s + 1, 1)]};
    // The side's quartic reduced to cubic (it is generic here, so compare with the full
    // quartic: the cross derivative is 4 (R(t) - E(t)), R cubic, E quartic).
    const BezierCurve r(row);
    for (double t : {0.0, 0.2, 0.5, 0.81, 1.0}) {
      const Vec2 x = p.domain().side_point(s, t);
      const SurfaceJet j = p.evaluate(x);
      EXPECT_LT(test::max_abs(j.p - curves[s].point(t)), 1e-14);
      const Vec2 d = opposite[s] - x;
      const Vec3 toward = d.x * j.su + d.y * j.sv;
      EXPECT_LT(test::max_abs(toward - 4.0 * (r.point(t) - curves[s].point(t))), 1e-13)
          << s << " " << t;
    }
  }
}

TEST(GregoryTri, CornersTakeTheLimits) {
  const T p(test::random_points(T::kPointCount, 7));
  const auto curves = p.boundary_curves();
  for (int s = 0; s < 3; ++s) {
    const Vec2 corner = p.domain().side_point(s, 0);
    const SurfaceJet j = p.evaluate(corner);
    const Vec2 du = p.domain().side_point(s, 1) - corner;
    EXPECT_LT(test::max_abs(du.x * j.su + du.y * j.sv - curves[s].derivative().point(0)), 1e-13);
    const Vec3 dd = du.x * du.x * j.suu + 2 * du.x * du.y * j.suv + du.y * du.y * j.svv;
    EXPECT_LT(test::max_abs(dd - curves[s].derivative().derivative().point(0)), 1e-12);
    const Vec2 dv = p.domain().side_point((s + 2) % 3, 0) - corner;
    EXPECT_LT(test::max_abs(dv.x * j.su + dv.y * j.sv + curves[(s + 2) % 3].derivative().point(1)),
              1e-13);
    for (double eps : {1e-4, 1e-7}) {
      const Vec2 x = corner + eps * (p.domain().interior_point() - corner);
      const SurfaceJet n = p.evaluate(x);
      EXPECT_LT(test::max_abs(n.p - j.p), 1e2 * eps);
      EXPECT_LT(test::max_abs(n.su - j.su), 1e2 * eps);
      EXPECT_LT(test::max_abs(n.sv - j.sv), 1e2 * eps);
    }
  }
}

TEST(GregoryTri, SceneRoundTripKeepsEveryPoint) {
  Scene s;
  s.patches.push_back({"t", std::make_shared<T>(test::random_points(T::kPointCount, 8))});
  const Scene back = parse_scene(scene_to_json(s), "mem");
  ASSERT_EQ(back.patches.size(), 1u);
  EXPECT_EQ(back.patches[0].patch->type(), "gregory-tri");
  EXPECT_EQ(back.patches[0].patch->control_points(), s.patches[0].patch->control_points());
  EXPECT_THROW(T(test::random_points(15, 1)), std::invalid_argument);
}

}  // namespace
}  // namespace pl
