#include "core/domain/unit_triangle.hpp"

#include <cassert>

namespace pl {

Vec2 UnitTriangleDomain::side_point(int side, double t) const {
  switch (side % 3) {
    case 0:
      return {t, 0};
    case 1:
      return {1 - t, t};
    default:
      return {0, 1 - t};
  }
}

Tessellation UnitTriangleDomain::tessellate(int n) const {
  assert(n >= 1);
  Tessellation t;
  t.density = n;
  // Row j (v = j/n) holds n - j + 1 points; id(i, j) is the point (i/n, j/n).
  std::vector<uint32_t> row_start(n + 2);
  for (int j = 0; j <= n; ++j) row_start[j + 1] = row_start[j] + (n - j + 1);
  const auto id = [&](int i, int j) { return row_start[j] + static_cast<uint32_t>(i); };
  t.points.reserve(row_start[n + 1]);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n - j; ++i) {
      double u = double(i) / n, v = double(j) / n;
      if (i + j == n) u = 1.0 - v;  // exactly on the hypotenuse
      t.points.emplace_back(u, v);
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n - j; ++i) {
      t.triangles.push_back({id(i, j), id(i + 1, j), id(i, j + 1)});
      if (i + 1 < n - j) t.triangles.push_back({id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  t.sides.assign(3, std::vector<uint32_t>(n + 1));
  for (int k = 0; k <= n; ++k) {
    t.sides[0][k] = id(k, 0);
    t.sides[1][k] = id(n - k, k);
    t.sides[2][k] = id(0, n - k);
  }
  snap_side_samples(*this, t);
  return t;
}

}  // namespace pl
