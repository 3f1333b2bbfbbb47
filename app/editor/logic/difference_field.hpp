// The comparison's difference colouring: the GB filling's meshes with the field the colour map
// reads (`mean`) replaced by each sample's signed distance to the Gregory filling of the same
// face (core/analysis/surface_distance.hpp), and the largest |distance| for a symmetric colour
// range. Recomputed only when its key (the document revision and which densities are shown)
// changes. GUI-free and unit-tested; the editor uploads scene() when follow() says it changed.
#pragma once

#include <cstdint>
#include <optional>

#include "app/editor/logic/surface_probe.hpp"
#include "render/draw_scene.hpp"

namespace pl {

class DifferenceField {
 public:
  // Returns true when recomputed for a new key.
  bool follow(const DrawScene& gregory, const DrawScene& gb, uint64_t key);
  void reset() { key_ = UINT64_MAX; }

  const DrawScene& scene() const { return scene_; }
  double max_abs() const { return max_abs_; }
  // The signed distance at a probe of the GB filling's drawn surfaces (the triangles this
  // field was computed on), nullopt when the probe is not on them.
  std::optional<double> distance_at(const ProbeHit& probe) const;
  // The symmetric colour range (never empty).
  double range() const { return max_abs_ > 0 ? max_abs_ : 1e-12; }

 private:
  DrawScene scene_;
  double max_abs_ = 0;
  uint64_t key_ = UINT64_MAX;
  uint64_t serial_ = 0;
};

}  // namespace pl
