// The GB patch of a network face with interior control (the face keys "degree" and "offsets",
// docs/scene-format.md): independent ribbons of degree d along their sides, l = ceil(d/2)
// layers (more on the sides of a concave face that need them, as in gb_face.cpp), and a central
// point.
//
//  - Layers 0 and 1 of ribbon i are the face side's cubic ribbon (the edge and the
//    Chiyokura–Kimura row) elevated exactly to degree d along the side and written in the ribbon's
//    cross-boundary degree m = 2l - 1: row 1 = row 0 + (3/m) (elevated inner row - row 0), so the
//    boundary curve and the cross-boundary derivative are the cubic ribbon's, whatever d is, and
//    neighbouring faces stay G1.
//  - The free points (layers k >= 2 at 2 <= j <= d-2, and the central point) start at their
//    defaults: the default-net rule (core/patch/gb/default_net.hpp) applied to the degree-d .gbp
//    net whose rings 0 and 1 are the elevated G1 data in degree d (a shared corner twist there
//    is the mean of the two ribbons' twists, which the .gbp net stores once). Ribbon i's row
//    k >= 2 is that net's row P^i_{0..d,k}, so a shared corner-block point is one value in both
//    ribbons; a stored offset is added to it (in both ribbons for a shared point).
//  - The central point: GBCentredRibbonPatch, its default the net's C_0.
// So the free points follow the boundary (defaults are recomputed from rings 0 and 1, offsets
// are kept), and degree 3 without offsets is exactly the face built by gb_face_patch.
#pragma once

#include <memory>
#include <span>
#include <vector>

#include "core/network/face_ribbons.hpp"
#include "core/patch/patch.hpp"
#include "core/scene/network.hpp"

namespace pl {

// The patch over the polygon `vertices` (domain vertex k = end of face side k) from ribbons
// already oriented for that domain. Throws std::invalid_argument for an unusable domain or a
// central-point offset the domain cannot carry.
std::unique_ptr<Patch> gb_interior_face_patch(const FaceRibbons& ribbons,
                                              std::vector<Vec2> vertices, int degree,
                                              std::span<const InteriorOffset> offsets);

// The default positions of the free points of the degree-d net of these ribbons, in .gbp order
// (GBPatch::point_count(n, d) points; rings 0 and 1 are the G1 data described above).
std::vector<Vec3> gb_face_default_net(const FaceRibbons& ribbons, int degree);

}  // namespace pl
