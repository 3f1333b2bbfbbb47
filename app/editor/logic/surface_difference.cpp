#include "app/editor/logic/surface_difference.hpp"

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

// Uniform grid over a point set: the nearest point by searching growing shells of cells.
class PointGrid {
 public:
  PointGrid(const std::vector<Vec3>& points) : points_(points) {
    lo_ = Vec3(std::numeric_limits<double>::infinity());
    Vec3 hi(-std::numeric_limits<double>::infinity());
    for (const Vec3& p : points) {
      lo_ = glm::min(lo_, p);
      hi = glm::max(hi, p);
    }
    const double extent = std::max({hi.x - lo_.x, hi.y - lo_.y, hi.z - lo_.z, 1e-12});
    // About one point per cell for surface-like sets.
    cell_ = extent / std::max(1.0, std::sqrt(double(points.size())));
    max_shell_ = static_cast<int>(std::ceil(extent / cell_)) + 2;
    for (std::size_t i = 0; i < points.size(); ++i) cells_[key(cell_of(points[i]))].push_back(i);
  }

  std::size_t nearest(const Vec3& p) const {
    const glm::ivec3 c = cell_of(p);
    std::size_t best = 0;
    double best_d2 = std::numeric_limits<double>::infinity();
    for (int r = 0; r <= max_shell_; ++r) {
      for (int i = -r; i <= r; ++i)
        for (int j = -r; j <= r; ++j)
          for (int k = -r; k <= r; ++k) {
            if (std::max({std::abs(i), std::abs(j), std::abs(k)}) != r) continue;
            const auto it = cells_.find(key(c + glm::ivec3(i, j, k)));
            if (it == cells_.end()) continue;
            for (std::size_t q : it->second) {
              const double d2 = glm::dot(points_[q] - p, points_[q] - p);
              if (d2 < best_d2) best_d2 = d2, best = q;
            }
          }
      // Every point outside shell r is at least r cells away.
      if (best_d2 <= (r * cell_) * (r * cell_)) break;
    }
    if (best_d2 == std::numeric_limits<double>::infinity())  // far from the set: plain search
      for (std::size_t q = 0; q < points_.size(); ++q) {
        const double d2 = glm::dot(points_[q] - p, points_[q] - p);
        if (d2 < best_d2) best_d2 = d2, best = q;
      }
    return best;
  }

 private:
  glm::ivec3 cell_of(const Vec3& p) const { return glm::ivec3(glm::floor((p - lo_) / cell_)); }
  static int64_t key(const glm::ivec3& c) {
    return (int64_t(c.x) * 73856093) ^ (int64_t(c.y) * 19349663) ^ (int64_t(c.z) * 83492791);
  }
  const std::vector<Vec3>& points_;
  Vec3 lo_;
  double cell_ = 1;
  int max_shell_ = 0;  // beyond it no cell of the set is left (queries lie near the set)
  std::unordered_map<int64_t, std::vector<std::size_t>> cells_;
};

}  // namespace

std::vector<double> signed_distance_to(const SurfaceMesh& from, const SurfaceMesh& to) {
  std::vector<double> out(from.positions.size(), 0.0);
  if (to.positions.empty() || to.triangles.empty()) return out;
  std::vector<std::vector<uint32_t>> around(to.positions.size());
  for (uint32_t t = 0; t < to.triangles.size(); ++t)
    for (uint32_t v : to.triangles[t]) around[v].push_back(t);
  const PointGrid grid(to.positions);
  for (std::size_t i = 0; i < from.positions.size(); ++i) {
    const Vec3& p = from.positions[i];
    const std::size_t n = grid.nearest(p);
    Vec3 best = to.positions[n];
    double best_d2 = glm::dot(best - p, best - p);
    for (uint32_t t : around[n]) {
      const auto& tri = to.triangles[t];
      const Vec3 q = closest_point_on_triangle(p, to.positions[tri[0]], to.positions[tri[1]],
                                               to.positions[tri[2]]);
      const double d2 = glm::dot(q - p, q - p);
      if (d2 < best_d2) best_d2 = d2, best = q;
    }
    const double d = std::sqrt(best_d2);
    out[i] = glm::dot(p - best, to.normals[n]) < 0 ? -d : d;
  }
  return out;
}

}  // namespace pl
