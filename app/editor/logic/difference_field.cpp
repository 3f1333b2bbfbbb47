#include "app/editor/logic/difference_field.hpp"

#include <algorithm>
#include <cmath>

#include "core/analysis/surface_distance.hpp"

namespace pl {

bool DifferenceField::follow(const DrawScene& gregory, const DrawScene& gb, uint64_t key) {
  if (key == key_) return false;
  key_ = key;
  scene_ = gb;
  max_abs_ = 0;
  for (std::size_t i = 0; i < scene_.surfaces.size() && i < gregory.surfaces.size(); ++i) {
    SurfaceMesh& m = scene_.surfaces[i];
    const SurfaceMesh& to = gregory.surfaces[i];
    m.mean = signed_distance_to(m.positions, {to.positions, to.normals, to.triangles});
    for (double v : m.mean) max_abs_ = std::max(max_abs_, std::abs(v));
    // Revisions of their own (high bit set, never an evaluator's), new at every recomputation,
    // so the GPU copy re-uploads every surface's new field.
    m.revision = ++serial_ | (1ull << 62);
  }
  return true;
}

std::optional<double> DifferenceField::distance_at(const ProbeHit& probe) const {
  if (key_ == UINT64_MAX || probe.surface < 0 ||
      std::size_t(probe.surface) >= scene_.surfaces.size())
    return {};
  const SurfaceMesh& m = scene_.surfaces[probe.surface];
  return probe_field(m, m.mean, probe);
}

}  // namespace pl
