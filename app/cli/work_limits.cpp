#include "app/cli/work_limits.hpp"

#include <algorithm>
#include <cmath>

#include "core/base/data_error.hpp"
#include "core/io/input_limits.hpp"
#include "core/patch/catmull_clark_patch.hpp"

namespace pl {

namespace {

// Samples of one surface with `sides` domain sides, per (density + 1)^2: the unit square's grid,
// the triangle's half, rings around a convex n-gon's centre (n/2), or a polygon domain's
// triangular grid at the boundary spacing (about n^2/11 for a regular n-gon), which is capped
// so that it grows linearly in n from 9 sides on (0.85 n measured for 16 to 64 sides;
// core/domain/concave_polygon.cpp).
double samples_per_square(int sides) {
  if (sides == 4) return 1.0;
  if (sides == 3) return 0.5;
  return std::max(0.5 * sides, std::min(0.1 * sides * sides, 0.9 * sides));
}

}  // namespace

std::size_t estimated_samples(const Scene& scene, int density) {
  const double square = (density + 1.0) * (density + 1.0);
  double total = 0;
  if (scene.network)
    for (const NetworkFace& f : scene.network->faces)
      total += samples_per_square(static_cast<int>(f.loop.size())) * square;
  for (const ScenePatch& sp : scene.patches) {
    // A Catmull-Clark entry is one square per ptex face (n per n-gon).
    if (const auto* cc = dynamic_cast<const CatmullClarkPatch*>(sp.patch.get())) {
      total += double(cc->limit().ptex_count()) * square;
      continue;
    }
    total += samples_per_square(sp.patch->domain().side_count()) * square;
  }
  for (const SceneCurve& c : scene.curves)  // a curve is cheap: samples per span
    total += double(curve_spans(c).size()) * (density + 1.0);
  return total > 1e18 ? std::size_t(1e18) : static_cast<std::size_t>(total);
}

void check_work_limits(const Scene& scene, int density, const std::string& source) {
  const std::size_t n = estimated_samples(scene, density);
  if (n <= kMaxSamples) return;
  // Samples grow with the square of the density.
  const int fits =
      std::max(1, static_cast<int>((density + 1) * std::sqrt(double(kMaxSamples) / double(n))) - 1);
  throw DataError(source, "",
                  "at density " + std::to_string(density) + " the scene takes about " +
                      std::to_string(n) + " samples; at most " + std::to_string(kMaxSamples) +
                      " are evaluated (use --density " + std::to_string(fits) + " or less)");
}

}  // namespace pl
