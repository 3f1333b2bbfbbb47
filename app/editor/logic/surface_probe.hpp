// The probe under the cursor: position, normal and curvatures at a ray's hit on the drawn
// tessellation, interpolated barycentrically from the exact per-sample values of the hit
// triangle. The editor finds the hit with its ScenePicker; probe_surfaces() tests every
// triangle (the reference). GUI-free and unit-tested.
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "app/editor/logic/triangle_bvh.hpp"
#include "core/mesh/surface_mesh.hpp"

namespace pl {

struct ProbeHit {
  int surface = -1;
  Vec3 position, normal;
  double k1 = 0, k2 = 0, gaussian = 0, mean = 0;  // k1 = kmax, k2 = kmin
  double distance = 0;                            // along the ray
  // Where on the drawn tessellation: triangle index and barycentric weights of its second and
  // third vertex (a field drawn on the same triangles is read there: probe_field).
  int triangle = -1;
  double b1 = 0, b2 = 0;
};

// A per-vertex field of `mesh` (the mesh the probe hit, or one with the same triangles)
// interpolated at the probe's point; nullopt when the field does not cover the triangle.
std::optional<double> probe_field(const SurfaceMesh& mesh, const std::vector<double>& field,
                                  const ProbeHit& probe);

// The values at `hit` (a triangle of `mesh`, which is surface `surface`) along `ray`.
ProbeHit probe_at(const SurfaceMesh& mesh, int surface, const TriangleHit& hit, const Ray& ray);

std::optional<ProbeHit> probe_surfaces(std::span<const SurfaceMesh> meshes, const Ray& ray);

}  // namespace pl
