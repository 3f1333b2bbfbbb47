#include "core/analysis/surface_distance.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

namespace pl {

Vec3 closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Vec3 bp = p - b;
  const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + (d1 / (d1 - d3)) * ab;
  const Vec3 cp = p - c;
  const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + (d2 / (d2 - d6)) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
  const double denom = 1 / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

namespace {

// Uniform grid over the triangles: each is listed in every cell its bounding box meets, so a
// triangle within distance d of a point has a cell at most ceil(d / cell) shells from the
// point's cell. The search visits growing shells and stops once the best distance found is
// within the shells visited: the closest point is exact (to rounding), not the nearest vertex's.
class TriangleGrid {
 public:
  explicit TriangleGrid(const TriangleSurface& s) : s_(s) {
    lo_ = Vec3(std::numeric_limits<double>::infinity());
    Vec3 hi(-std::numeric_limits<double>::infinity());
    for (const Vec3& p : s.positions) {
      lo_ = glm::min(lo_, p);
      hi = glm::max(hi, p);
    }
    const double extent = std::max({hi.x - lo_.x, hi.y - lo_.y, hi.z - lo_.z, 1e-300});
    // About one triangle per cell for surface-like sets.
    cell_ = extent / std::max(1.0, std::sqrt(double(s.triangles.size())));
    max_shell_ = static_cast<int>(std::ceil(extent / cell_)) + 2;
    for (uint32_t t = 0; t < s.triangles.size(); ++t) {
      Vec3 a(std::numeric_limits<double>::infinity()), b(-std::numeric_limits<double>::infinity());
      for (uint32_t v : s.triangles[t]) {
        a = glm::min(a, s.positions[v]);
        b = glm::max(b, s.positions[v]);
      }
      const glm::ivec3 c0 = cell_of(a), c1 = cell_of(b);
      for (int i = c0.x; i <= c1.x; ++i)
        for (int j = c0.y; j <= c1.y; ++j)
          for (int k = c0.z; k <= c1.z; ++k) cells_[key({i, j, k})].push_back(t);
    }
  }

  // The closest point of the surface to p and the triangle it lies on.
  std::pair<Vec3, uint32_t> closest(const Vec3& p) const {
    const glm::ivec3 c = cell_of(p);
    double best_d2 = std::numeric_limits<double>::infinity();
    Vec3 best(0);
    uint32_t best_t = 0;
    auto visit = [&](uint32_t t) {
      const auto& tri = s_.triangles[t];
      const Vec3 q = closest_point_on_triangle(p, s_.positions[tri[0]], s_.positions[tri[1]],
                                               s_.positions[tri[2]]);
      const double d2 = glm::dot(q - p, q - p);
      if (d2 < best_d2) best_d2 = d2, best = q, best_t = t;
    };
    // Shell r holds the cells at Chebyshev distance r from p's cell: every point outside the
    // shells up to r is more than r cells (r * cell_) away from p.
    for (int r = 0; r <= max_shell_ + distance_in_cells(c); ++r) {
      for (int i = -r; i <= r; ++i)
        for (int j = -r; j <= r; ++j)
          for (int k = -r; k <= r; ++k) {
            if (std::max({std::abs(i), std::abs(j), std::abs(k)}) != r) continue;
            const auto it = cells_.find(key(c + glm::ivec3(i, j, k)));
            if (it == cells_.end()) continue;
            for (uint32_t t : it->second) visit(t);
          }
      if (best_d2 <= (r * cell_) * (r * cell_)) break;
    }
    return {best, best_t};
  }

 private:
  glm::ivec3 cell_of(const Vec3& p) const { return glm::ivec3(glm::floor((p - lo_) / cell_)); }
  // How many shells p's cell lies outside the grid's box (far queries search that far first).
  int distance_in_cells(const glm::ivec3& c) const {
    const glm::ivec3 top = cell_of(lo_ + Vec3(cell_ * max_shell_));
    return std::max({0, -c.x, -c.y, -c.z, c.x - top.x, c.y - top.y, c.z - top.z});
  }
  static int64_t key(const glm::ivec3& c) {
    return (int64_t(c.x) * 73856093) ^ (int64_t(c.y) * 19349663) ^ (int64_t(c.z) * 83492791);
  }
  const TriangleSurface& s_;
  Vec3 lo_;
  double cell_ = 1;
  int max_shell_ = 0;
  std::unordered_map<int64_t, std::vector<uint32_t>> cells_;
};

}  // namespace

std::vector<double> signed_distance_to(std::span<const Vec3> from, const TriangleSurface& to) {
  std::vector<double> out(from.size(), 0.0);
  if (to.positions.empty() || to.triangles.empty()) return out;
  const TriangleGrid grid(to);
  for (std::size_t i = 0; i < from.size(); ++i) {
    const Vec3& p = from[i];
    const auto [q, t] = grid.closest(p);
    const auto& tri = to.triangles[t];
    // Signed by the triangle's vertex normals, summed: the side of the surface p is on.
    const Vec3 n = to.normals[tri[0]] + to.normals[tri[1]] + to.normals[tri[2]];
    const double d = glm::length(p - q);
    out[i] = glm::dot(p - q, n) < 0 ? -d : d;
  }
  return out;
}

}  // namespace pl
