// The signed distance from the samples of one surface to another's tessellation: what the
// comparison colours by and measures as "distance to the base scheme". Two schemes tessellate
// different domains (unit square, regular polygon, ...), so their samples do not correspond one
// to one and the same-parameter difference would measure the parameterizations, not the shapes;
// the distance is to the closest point of the other surface's triangles (exact: a uniform grid
// of the triangles searched in growing shells until no closer triangle can remain), signed by the
// other surface's vertex normals of that triangle.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "core/math/vec.hpp"

namespace pl {

// A tessellated surface as plain arrays (a SurfaceMesh's, or an evaluator's samples).
struct TriangleSurface {
  std::span<const Vec3> positions;
  std::span<const Vec3> normals;  // unit, one per position
  std::span<const std::array<uint32_t, 3>> triangles;
};

// One value per point of `from`: its signed distance to `to`.
std::vector<double> signed_distance_to(std::span<const Vec3> from, const TriangleSurface& to);

// Closest point of triangle abc to p (Ericson, Real-Time Collision Detection 5.1.5).
Vec3 closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

}  // namespace pl
