#include "core/domain/concave_polygon.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdio>
#include <map>
#include <mutex>
#include <optional>
#include <stdexcept>

#include "core/domain/polygon_triangulation.hpp"

namespace pl {

namespace {

// Closed segments ab and cd share a point.
bool segments_touch(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  const double d1 = cross(b - a, c - a), d2 = cross(b - a, d - a);
  const double d3 = cross(d - c, a - c), d4 = cross(d - c, b - c);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0)))
    return true;
  const auto on = [](Vec2 p, Vec2 q, Vec2 r, double o) {  // r on segment pq, given o = orient
    return o == 0 && std::min(p.x, q.x) <= r.x && r.x <= std::max(p.x, q.x) &&
           std::min(p.y, q.y) <= r.y && r.y <= std::max(p.y, q.y);
  };
  return on(a, b, c, d1) || on(a, b, d, d2) || on(c, d, a, d3) || on(c, d, b, d4);
}

bool inside(const std::vector<Vec2>& poly, Vec2 x) {
  bool in = false;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++)
    if ((poly[i].y > x.y) != (poly[j].y > x.y) &&
        x.x < poly[j].x + (x.y - poly[j].y) * (poly[i].x - poly[j].x) / (poly[i].y - poly[j].y))
      in = !in;
  return in;
}

// The interior point's grid search costs about 17,000 segment distances for a quad, and a
// network builds the same polygon (the regular n-gon) for every convex face: the result is
// remembered by the vertices' exact coordinates, for the last few hundred polygons.
class InteriorMemo {
 public:
  std::optional<Vec2> find(const std::vector<Vec2>& v) {
    std::lock_guard lock(mutex_);
    const auto it = memo_.find(key(v));
    if (it == memo_.end()) return std::nullopt;
    return it->second;
  }
  void keep(const std::vector<Vec2>& v, Vec2 interior) {
    std::lock_guard lock(mutex_);
    if (memo_.size() >= 256) memo_.clear();
    memo_.emplace(key(v), interior);
  }

 private:
  static std::vector<double> key(const std::vector<Vec2>& v) {
    std::vector<double> k;
    k.reserve(2 * v.size());
    for (const Vec2& p : v) k.push_back(p.x), k.push_back(p.y);
    return k;
  }
  std::mutex mutex_;
  std::map<std::vector<double>, Vec2> memo_;
};

InteriorMemo& interior_memo() {
  static InteriorMemo memo;
  return memo;
}

}  // namespace

double segment_distance(Vec2 x, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a;
  const double t = std::clamp(glm::dot(x - a, ab) / glm::dot(ab, ab), 0.0, 1.0);
  return glm::length(x - (a + t * ab));
}

ConcavePolygonDomain::ConcavePolygonDomain(std::vector<Vec2> vertices)
    : vertices_(std::move(vertices)), interior_(0) {
  const int n = static_cast<int>(vertices_.size());
  if (n < 3) throw std::invalid_argument("a polygon domain needs at least 3 vertices");
  for (const Vec2& v : vertices_)
    if (!std::isfinite(v.x) || !std::isfinite(v.y))
      throw std::invalid_argument("polygon domain has a non-finite vertex");
  for (int i = 0; i < n; ++i)
    if (vertex(i) == vertex(i - 1))
      throw std::invalid_argument("polygon domain side " + std::to_string(i) + " has zero length");
  // Adjacent sides may only share their common vertex (no fold-back); others nothing.
  for (int i = 0; i < n; ++i) {
    const Vec2 a = vertex(i - 1), b = vertex(i), c = vertex(i + 1);
    if (cross(b - a, c - b) == 0 && glm::dot(b - a, c - b) < 0)
      throw std::invalid_argument("polygon domain folds back at vertex " + std::to_string(i));
    for (int j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;
      if (segments_touch(vertex(i - 1), vertex(i), vertex(j - 1), vertex(j)))
        throw std::invalid_argument("polygon domain sides " + std::to_string(i) + " and " +
                                    std::to_string(j) + " intersect");
    }
  }
  if (!(area() > 0)) throw std::invalid_argument("polygon domain is not counter-clockwise");
  // A point well inside: the interior point farthest from the boundary among a grid's points.
  if (const auto known = interior_memo().find(vertices_)) {
    interior_ = *known;
    return;
  }
  Vec2 lo = vertices_[0], hi = vertices_[0];
  for (const Vec2& v : vertices_) lo = glm::min(lo, v), hi = glm::max(hi, v);
  double best = -1;
  constexpr int G = 64;
  for (int a = 0; a <= G; ++a)
    for (int b = 0; b <= G; ++b) {
      const Vec2 x = lo + Vec2(double(a) / G, double(b) / G) * (hi - lo);
      if (!inside(vertices_, x)) continue;
      double d = INFINITY;
      for (int i = 0; i < n; ++i) d = std::min(d, segment_distance(x, vertex(i - 1), vertex(i)));
      if (d > best) best = d, interior_ = x;
    }
  if (!(best > 0)) throw std::invalid_argument("polygon domain is too thin");
  interior_memo().keep(vertices_, interior_);
}

const Vec2& ConcavePolygonDomain::vertex(int i) const {
  const int n = static_cast<int>(vertices_.size());
  return vertices_[((i % n) + n) % n];
}

double ConcavePolygonDomain::area() const {
  double a = 0;
  for (int i = 0; i < side_count(); ++i) a += cross(vertex(i - 1), vertex(i));
  return 0.5 * a;
}

Vec2 ConcavePolygonDomain::side_point(int side, double t) const {
  return (1 - t) * vertex(side - 1) + t * vertex(side);
}

std::string ConcavePolygonDomain::key() const {
  std::string k = "concave";
  char buf[64];
  for (const Vec2& v : vertices_) {
    std::snprintf(buf, sizeof buf, ":%.17g,%.17g", v.x, v.y);
    k += buf;
  }
  return k;
}

Tessellation ConcavePolygonDomain::tessellate(int density) const {
  assert(density >= 1);
  const int n = side_count(), N = density;
  Tessellation t;
  t.density = N;
  // Boundary: side i contributes vertex i-1 and its N-1 inner samples.
  std::vector<double> spacing(n);
  double perimeter = 0;
  for (int i = 0; i < n; ++i) {
    const double len = glm::length(vertex(i) - vertex(i - 1));
    spacing[i] = len / N;
    perimeter += len;
    for (int k = 0; k < N; ++k) t.points.push_back(side_point(i, double(k) / N));
  }
  const std::size_t m = t.points.size();
  t.sides.assign(n, std::vector<uint32_t>(N + 1));
  for (int i = 0; i < n; ++i)
    for (int k = 0; k <= N; ++k) t.sides[i][k] = static_cast<uint32_t>((i * N + k) % m);
  // Interior: a triangular grid (slightly rotated, so its points are rarely cocircular or on
  // a side's line) at the mean boundary spacing, kept away from every side by more than half
  // that side's own spacing so no sliver forms against the boundary. With many sides the mean
  // boundary spacing shrinks like 1/n and the grid would grow like n^2: the spacing is kept at
  // least that of about kInteriorPerSide N^2 points per side (the ring tessellation of a convex
  // polygon has N^2 / 2), so the sample count grows linearly in n. Regular polygons of up to 8
  // sides (and the usual concave shapes) keep the mean boundary spacing.
  constexpr double kInteriorPerSide = 1 / (0.866 * 1.5);  // 0.866 h^2: area per grid point
  const double h = std::max(perimeter / (n * N), std::sqrt(area() / (kInteriorPerSide * n)) / N);
  const double rot = 0.1, c = std::cos(rot), s = std::sin(rot);
  Vec2 lo = vertices_[0], hi = vertices_[0];
  for (const Vec2& v : vertices_) lo = glm::min(lo, v), hi = glm::max(hi, v);
  const Vec2 mid = 0.5 * (lo + hi);
  const double R = 0.5 * glm::length(hi - lo) + h;
  const int rows = static_cast<int>(std::ceil(R / (h * std::sqrt(3.0) / 2)));
  const int cols = static_cast<int>(std::ceil(R / h)) + 1;
  for (int r = -rows; r <= rows; ++r)
    for (int q = -cols; q <= cols; ++q) {
      const Vec2 g((q + 0.5 * (r & 1)) * h, r * h * std::sqrt(3.0) / 2);
      const Vec2 x = mid + Vec2(c * g.x - s * g.y, s * g.x + c * g.y);
      if (!inside(vertices_, x)) continue;
      bool keep = true;
      for (int i = 0; i < n && keep; ++i)
        keep = segment_distance(x, vertex(i - 1), vertex(i)) > 0.6 * std::max(h, spacing[i]);
      if (keep) t.points.push_back(x);
    }
  std::vector<bool> used;
  std::vector<uint32_t> corners;
  for (int i = 0; i < n; ++i) corners.push_back(static_cast<uint32_t>(i * N));
  t.triangles = triangulate_polygon(t.points, m, corners, &used);
  // Drop skipped interior points (rare: exactly on an edge), renumbering the triangles.
  std::vector<uint32_t> renumber(t.points.size());
  std::size_t kept = 0;
  for (std::size_t i = 0; i < t.points.size(); ++i)
    if (used[i]) renumber[i] = static_cast<uint32_t>(kept), t.points[kept++] = t.points[i];
  t.points.resize(kept);
  for (auto& tri : t.triangles)
    for (uint32_t& v : tri) v = renumber[v];
  snap_side_samples(*this, t);
  return t;
}

}  // namespace pl
