#include "app/cli/work_limits.hpp"

#include <algorithm>
#include <cmath>

#include "core/base/data_error.hpp"
#include "core/io/input_limits.hpp"
#include "core/patch/patch_types.hpp"

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

namespace {

// What the estimate is made of: squares of (density + 1)^2 samples (surfaces) and curve spans of
// density + 1 samples each. Counted once; the estimate at any density follows.
struct WorkShape {
  double squares = 0, curve_spans = 0;
  std::size_t samples(int density) const {
    const double d = density + 1.0;
    const double total = squares * d * d + curve_spans * d;
    return total > 1e18 ? std::size_t(1e18) : static_cast<std::size_t>(total);
  }
};

WorkShape work_shape(const Scene& scene) {
  WorkShape w;
  if (scene.network)
    for (const NetworkFace& f : scene.network->faces)
      w.squares += samples_per_square(static_cast<int>(f.loop.size()));
  for (const ScenePatch& sp : scene.patches) {
    // A Catmull-Clark entry is one square per ptex face (n per n-gon).
    if (const auto* cc = patch_as<CatmullClarkPatch>(sp.patch.get())) {
      w.squares += double(cc->limit().ptex_count());
      continue;
    }
    w.squares += samples_per_square(sp.patch->domain().side_count());
  }
  // A curve costs per span: its samples (and a bounded number of quadrature points for its
  // length, and of polyline points and comb teeth when drawn).
  for (const SceneCurve& c : scene.curves) w.curve_spans += double(curve_span_count(c));
  return w;
}

int largest_density_within(const WorkShape& w, int density) {
  // The estimate grows with the density (as its square for surfaces, linearly for curves), so
  // the largest one within the bound is found by bisection.
  if (w.samples(1) > kMaxSamples) return 0;
  int lo = 1, hi = density;
  while (lo < hi) {
    const int mid = lo + (hi - lo + 1) / 2;
    if (w.samples(mid) <= kMaxSamples)
      lo = mid;
    else
      hi = mid - 1;
  }
  return lo;
}

}  // namespace

std::size_t estimated_samples(const Scene& scene, int density) {
  return work_shape(scene).samples(density);
}

int largest_density_within(const Scene& scene, int density) {
  return largest_density_within(work_shape(scene), density);
}

void check_work_limits(const Scene& scene, int density, const std::string& source) {
  const WorkShape w = work_shape(scene);
  const std::size_t n = w.samples(density);
  if (n <= kMaxSamples) return;
  const int fits = largest_density_within(w, density);
  const std::string head = "at density " + std::to_string(density) + " the scene takes about " +
                           std::to_string(n) + " samples; at most " + std::to_string(kMaxSamples) +
                           " are evaluated";
  if (fits > 0)
    throw DataError(source, "", head + " (use --density " + std::to_string(fits) + " or less)");
  // Not even density 1 fits: the scene itself is too big (a curve of millions of spans, say).
  throw DataError(source, "",
                  head + ", and " + std::to_string(w.samples(1)) +
                      " at --density 1: too many surfaces or curve spans for one command");
}

}  // namespace pl
