#include "core/domain/convex_polygon.hpp"

#include <cassert>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace pl {

ConvexPolygonDomain::ConvexPolygonDomain(std::vector<Vec2> vertices)
    : vertices_(std::move(vertices)), centre_(0) {
  const int n = static_cast<int>(vertices_.size());
  if (n < 3) throw std::invalid_argument("a polygon domain needs at least 3 vertices");
  for (int i = 0; i < n; ++i) {
    const Vec2 a = vertex(i - 1), b = vertex(i), c = vertex(i + 1);
    if (!(cross(b - a, c - b) > 0))
      throw std::invalid_argument("polygon domain is not strictly convex and counter-clockwise");
    centre_ += b;
  }
  centre_ /= double(n);
}

ConvexPolygonDomain ConvexPolygonDomain::regular(int n) {
  if (n < 3) throw std::invalid_argument("a regular polygon needs at least 3 sides");
  std::vector<Vec2> v;
  if (n == 4) {
    v = {{1, 1}, {-1, 1}, {-1, -1}, {1, -1}};
  } else {
    const double a = 2 * M_PI / n;
    for (int i = 0; i < n; ++i) v.emplace_back(std::cos(a * i), std::sin(a * i));
  }
  return ConvexPolygonDomain(std::move(v));
}

const Vec2& ConvexPolygonDomain::vertex(int i) const {
  const int n = static_cast<int>(vertices_.size());
  return vertices_[((i % n) + n) % n];
}

Vec2 ConvexPolygonDomain::side_point(int side, double t) const {
  return (1 - t) * vertex(side - 1) + t * vertex(side);
}

std::string ConvexPolygonDomain::key() const {
  std::string k = "convex";
  char buf[64];
  for (const Vec2& v : vertices_) {
    std::snprintf(buf, sizeof buf, ":%.17g,%.17g", v.x, v.y);
    k += buf;
  }
  return k;
}

Tessellation ConvexPolygonDomain::tessellate(int density) const {
  // Ring r (0..N) around the centre holds n*r points; on side i of ring r, point j (0..r-1) sits
  // at parameter j/r between the ring's scaled vertices i-1 and i. Ring N is the boundary, so
  // every side gets the N+1 samples k/N.
  assert(density >= 1);
  const int n = side_count(), N = density;
  Tessellation t;
  t.density = N;
  const auto id = [n](int r, int i, int j) -> uint32_t {
    if (r == 0) return 0;
    const int within = ((i % n + n) % n * r + j) % (n * r);
    return static_cast<uint32_t>(1 + n * r * (r - 1) / 2 + within);
  };
  t.points.reserve(1 + n * N * (N + 1) / 2);
  t.points.push_back(centre_);
  for (int r = 1; r <= N; ++r) {
    const double scale = r == N ? 1.0 : double(r) / N;
    for (int i = 0; i < n; ++i) {
      const Vec2 a = centre_ + scale * (vertex(i - 1) - centre_);
      const Vec2 b = centre_ + scale * (vertex(i) - centre_);
      for (int j = 0; j < r; ++j) {
        if (r == N && j == 0) {
          t.points.push_back(vertex(i - 1));  // exact domain vertices
        } else {
          const double s = double(j) / r;
          t.points.push_back(r == N ? side_point(i, s) : (1 - s) * a + s * b);
        }
      }
    }
  }
  for (int r = 1; r <= N; ++r)
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < r; ++j) {
        t.triangles.push_back({id(r, i, j), id(r, i, j + 1), id(r - 1, i, j)});
        if (j + 1 < r)
          t.triangles.push_back({id(r - 1, i, j), id(r, i, j + 1), id(r - 1, i, j + 1)});
      }
  t.sides.assign(n, std::vector<uint32_t>(N + 1));
  for (int i = 0; i < n; ++i)
    for (int k = 0; k <= N; ++k) t.sides[i][k] = id(N, i, k);
  snap_side_samples(*this, t);
  return t;
}

}  // namespace pl
