// The Chiyokura–Kimura construction (H. Chiyokura, F. Kimura, "Design of solids with free-form
// surfaces", SIGGRAPH 1983) of cross-boundary tangent fields along
// one network edge. With c(t) the edge derivative and b(t) the linear interpolation of
// b0 = unit(n0 x c(0)) and b3 = unit(n1 x c(1)) (n0, n1 the end vertices' tangent-plane
// normals), every face using the edge gets the field
//     a(t) = k(t) b(t) + h(t) c(t),   k, h linear,
// with k, h fixed at each end by that face's neighbouring edge tangent there (projected onto
// the tangent plane). All fields of the edge lie in span(b(t), c(t)), so the faces sharing it
// are G1 along it; an edge used by one face gets the same field, which interpolates the end
// tangents its neighbouring edges give.
#pragma once

#include <array>
#include <vector>

#include "core/network/tangent_planes.hpp"

namespace pl {

// One field per use of the edge, parallel to topology.edge_faces[e]: the cubic Bézier control
// vectors a_0..a_3 of a(t) in the edge's own parameter t (from v[0] to v[1]). a_0 and a_3 are
// the face's neighbouring edge tangents leaving the end vertices, unprojected (they are the
// patch corners' actual derivatives); a_1, a_2 are the construction's:
//   a_1 = (k1 - k0) b0/3 + k0 b1 + 2 h0 c1/3 + h1 c0/3
//   a_2 = k1 b2 - (k1 - k0) b3/3 + h0 c2/3 + 2 h1 c1/3
// where b1 = (2 b0 + b3)/3, b2 = (b0 + 2 b3)/3 and c_j = 3 (P_{j+1} - P_j).
struct EdgeCrossTangents {
  std::vector<std::array<Vec3, 4>> fields;
};

// Throws DataError (empty source) naming the edge when b(t) vanishes (its end planes make it
// turn half a revolution). planes must be defined at both end vertices if a face uses e.
EdgeCrossTangents edge_cross_tangents(const Network& network, const NetworkTopology& topology,
                                      const std::vector<TangentPlane>& planes, int edge);

}  // namespace pl
