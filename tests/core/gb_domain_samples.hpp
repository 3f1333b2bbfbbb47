// Sample points of the regular n-gon domain for the GB patch, default-net and elevation tests.
#pragma once

#include <random>
#include <vector>

#include "core/domain/convex_polygon.hpp"

namespace pl::test {

// Random points of the polygon at least `margin` inside every side (rejection sampling).
inline std::vector<Vec2> polygon_interior(const ConvexPolygonDomain& dom, int count, unsigned seed,
                                          double margin) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> r(-1, 1);
  std::vector<Vec2> out;
  const int n = dom.side_count();
  while (static_cast<int>(out.size()) < count) {
    const Vec2 x(r(rng), r(rng));
    bool inside = true;
    for (int i = 0; i < n; ++i) {
      const Vec2 a = dom.vertex(i - 1), e = glm::normalize(dom.vertex(i) - a);
      if (e.x * (x.y - a.y) - e.y * (x.x - a.x) < margin) inside = false;
    }
    if (inside) out.push_back(x);
  }
  return out;
}

// per_side + 1 points on every side, both vertices included.
inline std::vector<Vec2> polygon_sides(const ConvexPolygonDomain& dom, int per_side) {
  std::vector<Vec2> out;
  for (int i = 0; i < dom.side_count(); ++i)
    for (int t = 0; t <= per_side; ++t) out.push_back(dom.side_point(i, double(t) / per_side));
  return out;
}

}  // namespace pl::test
