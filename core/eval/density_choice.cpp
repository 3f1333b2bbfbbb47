#include "core/eval/density_choice.hpp"

#include <algorithm>
#include <cmath>

namespace pl {

namespace {

double triangles_at(const SurfaceSize& s, int density) {
  const double r = double(density) / std::max(1, s.density);
  return double(s.triangles) * r * r;
}

}  // namespace

Sphere bounding_sphere(const Patch& patch) {
  Sphere s;
  const auto& pts = patch.control_points();
  if (pts.empty()) return s;
  for (const Vec3& p : pts) s.centre += p;
  s.centre /= double(pts.size());
  for (const Vec3& p : pts) s.radius = std::max(s.radius, glm::length(p - s.centre));
  return s;
}

std::vector<int> density_levels(const DensityBudget& b) {
  std::vector<int> levels;
  for (int d = std::max(1, b.max_density); d >= std::max(1, b.min_density); d /= 2) {
    levels.push_back(d);
    if (d == 1) break;
  }
  if (levels.empty()) levels.push_back(std::max(1, b.max_density));
  return levels;
}

std::vector<int> choose_densities(std::span<const SurfaceSize> sizes, const DensityBudget& b) {
  if (sizes.empty()) return {};
  const std::vector<int> levels = density_levels(b);  // finest first
  const int coarsest = int(levels.size()) - 1;
  std::vector<int> level(sizes.size());
  for (std::size_t i = 0; i < sizes.size(); ++i) {
    const double need = sizes[i].pixels / b.pixels_per_segment;
    int l = 0;
    while (l < coarsest && levels[l + 1] >= need) ++l;  // the coarsest level that is enough
    if (l > 0 && sizes[i].fitted && sizes[i].density == levels[l - 1]) --l;  // keep one finer
    level[i] = l;
  }
  const auto total = [&] {
    double t = 0;
    for (std::size_t i = 0; i < sizes.size(); ++i) t += triangles_at(sizes[i], levels[level[i]]);
    return t;
  };
  // Over the budget: the finest surfaces go down a level, until it fits or all are coarsest.
  while (total() > double(b.triangles)) {
    const int finest = *std::min_element(level.begin(), level.end());
    if (finest >= coarsest) break;
    for (int& l : level)
      if (l == finest) ++l;
  }
  std::vector<int> out(sizes.size());
  for (std::size_t i = 0; i < sizes.size(); ++i) out[i] = levels[level[i]];
  return out;
}

int uniform_density(std::span<const SurfaceSize> sizes, const DensityBudget& b) {
  const std::vector<int> levels = density_levels(b);
  for (int d : levels) {
    double t = 0;
    for (const SurfaceSize& s : sizes) t += triangles_at(s, d);
    if (t <= double(b.triangles)) return d;
  }
  return levels.back();
}

}  // namespace pl
