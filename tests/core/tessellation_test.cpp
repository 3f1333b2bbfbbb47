// Tessellations: counts, orientation, and side samples at the exact side parameters k/N.
#include <gtest/gtest.h>

#include "core/domain/convex_polygon.hpp"
#include "core/domain/unit_square.hpp"
#include "core/domain/unit_triangle.hpp"

namespace pl {
namespace {

double signed_area(const Tessellation& t, const std::array<uint32_t, 3>& tri) {
  const Vec2 a = t.points[tri[0]], b = t.points[tri[1]], c = t.points[tri[2]];
  return 0.5 * ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
}

void check(const Domain& d, int N, double area) {
  const Tessellation t = d.tessellate(N);
  double total = 0;
  for (const auto& tri : t.triangles) {
    for (uint32_t i : tri) ASSERT_LT(i, t.points.size());
    const double a = signed_area(t, tri);
    EXPECT_GT(a, 0) << d.key() << " N=" << N;  // counter-clockwise, no slivers
    total += a;
  }
  EXPECT_NEAR(total, area, 1e-12 * area) << d.key();  // covers the domain exactly once
  ASSERT_EQ(t.sides.size(), static_cast<std::size_t>(d.side_count()));
  for (int s = 0; s < d.side_count(); ++s) {
    ASSERT_EQ(t.sides[s].size(), static_cast<std::size_t>(N + 1));
    for (int k = 0; k <= N; ++k) {
      const Vec2 expect = d.side_point(s, double(k) / N);
      EXPECT_EQ(t.points[t.sides[s][k]], expect) << d.key() << " side " << s << " k " << k;
    }
    // Consecutive sides share their corner sample.
    EXPECT_EQ(t.sides[s].back(), t.sides[(s + 1) % d.side_count()].front());
  }
}

TEST(Tessellation, SquareTriangleAndPolygons) {
  for (int N : {1, 2, 7, 32}) {
    check(UnitSquareDomain(), N, 1.0);
    check(UnitTriangleDomain(), N, 0.5);
    for (int n = 3; n <= 12; ++n) {
      const auto poly = ConvexPolygonDomain::regular(n);
      const double area = n == 4 ? 4.0 : 0.5 * n * std::sin(2 * M_PI / n);
      check(poly, N, area);
    }
  }
}

TEST(Tessellation, PointCounts) {
  EXPECT_EQ(UnitSquareDomain().tessellate(10).points.size(), 121u);
  EXPECT_EQ(UnitTriangleDomain().tessellate(10).points.size(), 66u);
  EXPECT_EQ(ConvexPolygonDomain::regular(5).tessellate(10).points.size(), 1u + 5 * 55);
}

TEST(Tessellation, PolygonDomainRejectsNonConvexInput) {
  EXPECT_THROW(ConvexPolygonDomain({{0, 0}, {1, 0}}), std::invalid_argument);
  EXPECT_THROW(ConvexPolygonDomain({{0, 0}, {0, 1}, {1, 0}}), std::invalid_argument);  // clockwise
  EXPECT_THROW(ConvexPolygonDomain({{0, 0}, {2, 0}, {1, 0.1}, {2, 2}, {0, 2}}),
               std::invalid_argument);
}

}  // namespace
}  // namespace pl
