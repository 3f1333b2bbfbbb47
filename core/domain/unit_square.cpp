#include "core/domain/unit_square.hpp"

#include <cassert>

namespace pl {

Vec2 UnitSquareDomain::side_point(int side, double t) const {
  switch (side & 3) {
    case 0:
      return {t, 0};
    case 1:
      return {1, t};
    case 2:
      return {1 - t, 1};
    default:
      return {0, 1 - t};
  }
}

Tessellation UnitSquareDomain::tessellate(int n) const {
  assert(n >= 1);
  Tessellation t;
  t.density = n;
  const auto id = [n](int i, int j) { return static_cast<uint32_t>(j * (n + 1) + i); };
  t.points.reserve((n + 1) * (n + 1));
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      // i == n is written as exactly 1 so that side samples sit on the side parameters k/n.
      t.points.emplace_back(i == n ? 1.0 : double(i) / n, j == n ? 1.0 : double(j) / n);
  t.triangles.reserve(2 * n * n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      t.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      t.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  t.sides.assign(4, std::vector<uint32_t>(n + 1));
  for (int k = 0; k <= n; ++k) {
    t.sides[0][k] = id(k, 0);
    t.sides[1][k] = id(n, k);
    t.sides[2][k] = id(n - k, n);
    t.sides[3][k] = id(0, n - k);
  }
  snap_side_samples(*this, t);
  return t;
}

}  // namespace pl
