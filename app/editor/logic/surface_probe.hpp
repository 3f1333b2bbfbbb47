// The probe under the cursor: position, normal and curvatures at a ray's hit on the drawn
// tessellation, interpolated barycentrically from the exact per-sample values of the hit
// triangle. The editor finds the hit with its ScenePicker; probe_surfaces() tests every
// triangle (the reference). GUI-free and unit-tested.
#pragma once

#include <optional>
#include <span>

#include "app/editor/logic/triangle_bvh.hpp"
#include "core/mesh/surface_mesh.hpp"

namespace pl {

struct ProbeHit {
  int surface = -1;
  Vec3 position, normal;
  double k1 = 0, k2 = 0, gaussian = 0, mean = 0;  // k1 = kmax, k2 = kmin
  double distance = 0;                            // along the ray
};

// The values at `hit` (a triangle of `mesh`, which is surface `surface`) along `ray`.
ProbeHit probe_at(const SurfaceMesh& mesh, int surface, const TriangleHit& hit, const Ray& ray);

std::optional<ProbeHit> probe_surfaces(std::span<const SurfaceMesh> meshes, const Ray& ray);

}  // namespace pl
