// Moving, turning and scaling part of a curve network as one rigid piece (a similarity), so that
// every vertex keeps its tangent plane consistent: a transformed vertex takes all its handles
// and its fixed normal along (the plane turns with a rotation, keeps its orientation under a
// scale), and a vertex left in place keeps its handles and plane. Faces stay G1 because every
// end tangent stays in its vertex's plane, as for any other edit (handle_planes.hpp).
#pragma once

#include <array>
#include <span>

#include "core/math/similarity.hpp"
#include "core/scene/network.hpp"

namespace pl {

// Applies `t` to the vertices `vertices`, to every handle at them and to their fixed normals
// (turned). `handles` ({edge, end}) at vertices outside that set are moved by `t` too and then
// kept in their vertex's plane (constrained_handle), as a handle drag keeps them. Everything else
// is unchanged. Refused (EditRefused, network unchanged): an invalid similarity, an index that
// does not exist.
void transform_network(Network& network, std::span<const int> vertices,
                       std::span<const std::array<int, 2>> handles, const Similarity& t);

}  // namespace pl
