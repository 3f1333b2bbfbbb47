// Concave polygon domain: validation, tessellation (orientation, exact coverage, side samples at
// k/N, triangle shape) and mean value coordinates (Lagrange, reproduction, derivatives).
#include <gtest/gtest.h>

#include <cmath>

#include "core/domain/concave_polygon.hpp"
#include "core/domain/polygon_triangulation.hpp"
#include "core/param/mean_value.hpp"

namespace pl {
namespace {

const std::vector<Vec2> kL = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
const std::vector<Vec2> kU = {{0, 0}, {3, 0}, {3, 2}, {2, 2}, {2, 0.8}, {1, 0.8}, {1, 2}, {0, 2}};
const std::vector<Vec2> kStar = [] {
  std::vector<Vec2> v;
  for (int i = 0; i < 10; ++i) {
    const double a = 2 * M_PI * i / 10, r = i % 2 ? 0.45 : 1.0;
    v.emplace_back(r * std::cos(a), r * std::sin(a));
  }
  return v;
}();

double signed_area(const Tessellation& t, const std::array<uint32_t, 3>& tri) {
  const Vec2 a = t.points[tri[0]], b = t.points[tri[1]], c = t.points[tri[2]];
  return 0.5 * ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
}

// Smallest angle of a triangle in degrees.
double min_angle(const Tessellation& t, const std::array<uint32_t, 3>& tri) {
  double m = 180;
  for (int i = 0; i < 3; ++i) {
    const Vec2 a = t.points[tri[i]], b = t.points[tri[(i + 1) % 3]], c = t.points[tri[(i + 2) % 3]];
    const double cosv = glm::dot(b - a, c - a) / (glm::length(b - a) * glm::length(c - a));
    m = std::min(m, std::acos(std::clamp(cosv, -1.0, 1.0)) * 180 / M_PI);
  }
  return m;
}

void check(const ConcavePolygonDomain& d, int N) {
  const Tessellation t = d.tessellate(N);
  double total = 0, worst = 180;
  for (const auto& tri : t.triangles) {
    for (uint32_t i : tri) ASSERT_LT(i, t.points.size());
    const double a = signed_area(t, tri);
    EXPECT_GT(a, 0) << d.key() << " N=" << N;
    total += a;
    worst = std::min(worst, min_angle(t, tri));
  }
  // Shoelace area of the input polygon, computed here independently of the domain.
  double area = 0;
  const auto& v = d.vertices();
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Vec2 a = v[i], b = v[(i + 1) % v.size()];
    area += 0.5 * (a.x * b.y - a.y * b.x);
  }
  EXPECT_NEAR(total, area, 1e-12 * area) << d.key() << " N=" << N;
  // Every point is used: the triangle count of a triangulated disk is 2V - B - 2.
  EXPECT_EQ(t.triangles.size(), 2 * t.points.size() - d.side_count() * N - 2);
  // Well-shaped: the constrained Delaunay triangulation of a regular interior grid.
  if (N >= 4) {
    EXPECT_GT(worst, 15.0) << d.key() << " N=" << N;
  }
  ASSERT_EQ(t.sides.size(), static_cast<std::size_t>(d.side_count()));
  for (int s = 0; s < d.side_count(); ++s) {
    ASSERT_EQ(t.sides[s].size(), static_cast<std::size_t>(N + 1));
    for (int k = 0; k <= N; ++k)
      EXPECT_EQ(t.points[t.sides[s][k]], d.side_point(s, double(k) / N)) << s << " " << k;
    EXPECT_EQ(t.sides[s].back(), t.sides[(s + 1) % d.side_count()].front());
    EXPECT_EQ(t.points[t.sides[s].front()], v[(s + v.size() - 1) % v.size()]);
  }
}

TEST(ConcaveDomain, Tessellation) {
  for (int N : {1, 2, 5, 16, 40}) {
    check(ConcavePolygonDomain(kL), N);
    check(ConcavePolygonDomain(kU), N);
    check(ConcavePolygonDomain(kStar), N);
    std::vector<Vec2> hex;
    for (int i = 0; i < 6; ++i) hex.emplace_back(std::cos(M_PI * i / 3), std::sin(M_PI * i / 3));
    check(ConcavePolygonDomain(hex), N);
  }
}

// An axis-aligned interior grid has many points exactly on edges between earlier points of
// their row or column (whatever the insertion order): each must split that edge, not be dropped.
TEST(PolygonTriangulation, CollinearInteriorPointsAreAllUsed) {
  const int N = 12;
  std::vector<Vec2> p;
  for (int k = 0; k < N; ++k) p.emplace_back(k, 0);
  for (int k = 0; k < N; ++k) p.emplace_back(N, k);
  for (int k = 0; k < N; ++k) p.emplace_back(N - k, N);
  for (int k = 0; k < N; ++k) p.emplace_back(0, N - k);
  const std::size_t m = p.size();
  for (int i = 1; i < N; ++i)
    for (int j = 1; j < N; ++j) p.emplace_back(i, j);
  std::vector<bool> used;
  const auto tris = triangulate_polygon(p, m, {0, N, 2 * N, 3 * N}, &used);
  EXPECT_EQ(std::count(used.begin(), used.end(), true), long(p.size()));
  EXPECT_EQ(tris.size(), 2 * p.size() - m - 2);
  double area = 0;
  for (const auto& t : tris) {
    const Vec2 a = p[t[0]], b = p[t[1]], c = p[t[2]];
    const double twice = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    EXPECT_GT(twice, 0);
    area += 0.5 * twice;
  }
  EXPECT_DOUBLE_EQ(area, double(N * N));
}

TEST(ConcaveDomain, RejectsInvalidPolygons) {
  EXPECT_THROW(ConcavePolygonDomain({{0, 0}, {1, 0}}), std::invalid_argument);
  EXPECT_THROW(ConcavePolygonDomain({{0, 0}, {0, 1}, {1, 0}}), std::invalid_argument);  // CW
  EXPECT_THROW(ConcavePolygonDomain({{0, 0}, {1, 0}, {1, 0}, {0, 1}}), std::invalid_argument);
  // Bow tie.
  EXPECT_THROW(ConcavePolygonDomain({{0, 0}, {1, 1}, {1, 0}, {0, 1}}), std::invalid_argument);
  // Touching: vertex 4 lies on side 1.
  EXPECT_THROW(ConcavePolygonDomain({{0, 0}, {2, 0}, {2, 2}, {1, 2}, {1, 0}, {0, 1}}),
               std::invalid_argument);
  // Folding back along a side.
  EXPECT_THROW(ConcavePolygonDomain({{0, 0}, {2, 0}, {1, 0}, {1, 1}}), std::invalid_argument);
}

TEST(MeanValue, PartitionReproductionLagrangeAndSides) {
  for (const auto& poly : {kL, kU, kStar}) {
    const ConcavePolygonDomain d(poly);
    const Tessellation t = d.tessellate(12);
    std::vector<Jet> lam(poly.size());
    for (const Vec2& x : t.points) {
      bool vertex = false;
      for (const Vec2& v : poly) vertex |= v == x;
      if (vertex) continue;
      mean_value_coordinates(poly, x, lam);
      Jet sum(0.0), px(0.0), py(0.0);
      for (std::size_t i = 0; i < poly.size(); ++i) {
        sum += lam[i];
        px += poly[i].x * lam[i];
        py += poly[i].y * lam[i];
      }
      // Partition of unity and linear precision, with their derivatives.
      EXPECT_NEAR(sum.f, 1, 1e-12);
      EXPECT_NEAR(px.f, x.x, 1e-12);
      EXPECT_NEAR(py.f, x.y, 1e-12);
      EXPECT_NEAR(px.fu, 1, 1e-9);
      EXPECT_NEAR(px.fv, 0, 1e-9);
      EXPECT_NEAR(py.fv, 1, 1e-9);
      EXPECT_NEAR(px.fuu, 0, 1e-7);
      EXPECT_NEAR(py.fuv, 0, 1e-7);
    }
    // On side s the coordinates are the linear interpolant of its two vertices.
    const int n = static_cast<int>(poly.size());
    for (int s = 0; s < n; ++s)
      for (double a : {0.1, 0.5, 0.77}) {
        mean_value_coordinates(poly, d.side_point(s, a), lam);
        for (int i = 0; i < n; ++i) {
          const double expect = i == s ? a : i == (s + n - 1) % n ? 1 - a : 0.0;
          EXPECT_NEAR(lam[i].f, expect, 1e-14) << s << " " << i;
        }
      }
  }
}

TEST(MeanValue, DerivativesMatchFiniteDifferences) {
  // Gradient against central differences of the values, Hessian against central differences of
  // the gradient (h = 1e-5 keeps the h^2 truncation small even 0.07 from the reflex vertex).
  std::vector<Jet> l0(kL.size()), lp(kL.size()), lm(kL.size());
  const double h = 1e-5;
  for (Vec2 x : {Vec2(0.5, 0.5), Vec2(1.5, 0.3), Vec2(0.3, 1.7), Vec2(0.95, 0.95)}) {
    mean_value_coordinates(kL, x, l0);
    for (int dir = 0; dir < 2; ++dir) {
      const Vec2 e = dir == 0 ? Vec2(h, 0) : Vec2(0, h);
      mean_value_coordinates(kL, x + e, lp);
      mean_value_coordinates(kL, x - e, lm);
      for (std::size_t i = 0; i < kL.size(); ++i) {
        EXPECT_NEAR(dir == 0 ? l0[i].fu : l0[i].fv, (lp[i].f - lm[i].f) / (2 * h), 1e-8);
        const double du = (lp[i].fu - lm[i].fu) / (2 * h), dv = (lp[i].fv - lm[i].fv) / (2 * h);
        EXPECT_NEAR(dir == 0 ? l0[i].fuu : l0[i].fuv, du, 1e-6);
        EXPECT_NEAR(dir == 0 ? l0[i].fuv : l0[i].fvv, dv, 1e-6);
      }
    }
  }
}

// Near a side the rescaled form must agree with the interior limit (continuity of all jets).
TEST(MeanValue, SideValuesAreInteriorLimits) {
  std::vector<Jet> on(kL.size()), in(kL.size());
  const Vec2 x = ConcavePolygonDomain(kL).side_point(4, 0.3);  // side from (1,2) to (0,2)
  mean_value_coordinates(kL, x, on);
  mean_value_coordinates(kL, x - Vec2(0, 1e-7), in);
  for (std::size_t i = 0; i < kL.size(); ++i) {
    EXPECT_NEAR(on[i].fu, in[i].fu, 1e-5);
    EXPECT_NEAR(on[i].fv, in[i].fv, 1e-5);
    EXPECT_NEAR(on[i].fuu, in[i].fuu, 1e-4);
    EXPECT_NEAR(on[i].fvv, in[i].fvv, 1e-4);
  }
}

}  // namespace
}  // namespace pl
