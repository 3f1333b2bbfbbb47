// The probe under the cursor: the ray is cast against the drawn tessellation (Moller-Trumbore),
// and position, normal and curvatures are interpolated barycentrically from the exact per-sample
// values of the hit triangle. GUI-free and unit-tested.
#pragma once

#include <optional>
#include <span>

#include "app/editor/logic/view_math.hpp"
#include "core/mesh/surface_mesh.hpp"

namespace pl {

struct ProbeHit {
  int surface = -1;
  Vec3 position, normal;
  double k1 = 0, k2 = 0, gaussian = 0, mean = 0;  // k1 = kmax, k2 = kmin
  double distance = 0;                            // along the ray
};

std::optional<ProbeHit> probe_surfaces(std::span<const SurfaceMesh> meshes, const Ray& ray);

}  // namespace pl
