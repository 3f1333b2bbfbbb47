// Networks built from a formula, for benchmarks, tests and `patchlab sample`: every end tangent
// at a vertex lies in the surface's tangent plane there, so a G1 filling exists.
#pragma once

#include <vector>

#include "core/scene/network.hpp"

namespace pl {

// Edge a-b on the unit sphere: the cubic whose handles lie along the great circle through the two
// vertices, with the handle length 4/3 tan(angle / 4) that makes it close to the arc.
NetworkEdge sphere_edge(const std::vector<Vec3>& vertices, int a, int b);

// A closed quad network on the unit sphere: each face of the cube [-1, 1]^3 cut into k x k cells,
// every grid point projected onto the sphere. 6 k^2 faces, 12 k^2 edges, 6 k^2 + 2 vertices;
// loops are oriented outwards. k >= 1. Faces are named "x+3.1" (cube side, row, column).
Network cube_sphere_network(int k, FaceScheme scheme = FaceScheme::Auto);

}  // namespace pl
