// The comparison's difference mode: for every sample of one filling (GB), its signed distance to
// the other filling (Gregory) of the same face. The two schemes tessellate different domains
// (unit square vs regular polygon), so interior samples do not correspond one to one; the
// distance is to the nearest point of the other surface's tessellation (nearest sample found
// with a uniform grid, then the closest point on the triangles around it), signed by the other
// surface's normal there. GUI-free and unit-tested.
#pragma once

#include <vector>

#include "core/mesh/surface_mesh.hpp"

namespace pl {

// One value per vertex of `from`: signed distance to `to`.
std::vector<double> signed_distance_to(const SurfaceMesh& from, const SurfaceMesh& to);

// Closest point of triangle abc to p (Ericson, Real-Time Collision Detection 5.1.5).
Vec3 closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

}  // namespace pl
