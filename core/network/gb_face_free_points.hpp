// The free control points of a network GB face (docs/scene-format.md, "Interior control"): the
// points a designer moves, each with its default position (the default-net rule on the face's
// G1 data, gb_face_default_net) and its stored offset. What the editor lists, draws and drags;
// setting a point's position stores position - default as its offset.
#pragma once

#include <span>
#include <vector>

#include "core/network/chiyokura_kimura.hpp"
#include "core/network/face_ribbons.hpp"
#include "core/network/tangent_planes.hpp"

namespace pl {

struct FreePoint {
  InteriorOffset name;  // the centre or [side, j, layer]; name.by is zero
  Vec3 default_position{0};
  Vec3 offset{0};  // the stored offset, zero when the point has none
  Vec3 position() const { return default_position + offset; }
};

// One name per free point of a face of `sides` sides and degree d: the centre, then layer by
// layer (k = 2 .. l-1) side by side, j = k .. d-1-k. The other names of a corner-block point
// (docs/scene-format.md) are aliases of these.
std::vector<InteriorOffset> gb_face_free_point_names(int sides, int degree);

// Whether two names (each valid for the face) are one control point (interior_point_index).
bool same_interior_point(int sides, int degree, const InteriorOffset& a, const InteriorOffset& b);

// The free points of the face with these ribbons (as face_ribbons gives them: the network's), in
// gb_face_free_point_names order, with the offsets of
// `offsets` (matched by point, whichever name they use). Throws std::invalid_argument like
// gb_face_default_net.
std::vector<FreePoint> gb_face_free_points(const FaceRibbons& ribbons, int degree,
                                           std::span<const InteriorOffset> offsets);

// The ribbons of face f from the tangent planes at its vertices, computing the fields of its
// edges only: cost local to the face. `cross` is scratch (grown to the edge count; entries of
// the face's edges overwritten). Throws DataError (empty source) like build_face_ribbons.
FaceRibbons face_ribbons_from_planes(const Network& network, const NetworkTopology& topology,
                                     const std::vector<TangentPlane>& planes, int face,
                                     std::vector<EdgeCrossTangents>& cross);

// The same from the network alone (the planes of the face's vertices are built here).
FaceRibbons local_face_ribbons(const Network& network, const NetworkTopology& topology, int face);

// Offsets with `name`'s entry set to `by` (replacing the entry naming the same point under any
// name; removed when `by` is zero).
std::vector<InteriorOffset> with_offset(int sides, int degree, std::vector<InteriorOffset> offsets,
                                        const InteriorOffset& name, const Vec3& by);

}  // namespace pl
