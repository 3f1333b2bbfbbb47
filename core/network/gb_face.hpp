// GB patches (independent ribbons, SMI 2018) of network faces with any number of sides,
// convex or concave, built from the same Chiyokura–Kimura ribbons as the Gregory faces.
// Face side i becomes domain side i (from domain vertex i-1 to vertex i), traversed the same way
// with the same parameter, so patch_side is the identity and Su x Sv points to the face's
// outward side.
#pragma once

#include <memory>
#include <vector>

#include "core/network/face_ribbons.hpp"
#include "core/patch/gb/gb_ribbon_patch.hpp"

namespace pl {

// Domain choice. Convex faces (every corner turns left, judged from the ribbons) get the regular
// n-gon: the same fixed, symmetric kind of domain the Gregory faces use, so a comparison of the
// two schemes differs in the blending only, not in a shape-dependent parameterisation. Faces
// with a reflex corner get the angle + arc-length heuristic (it follows curved boundaries, where
// a projection can fold), and the best-fit-plane projection if that heuristic's polygon is not
// usable.
enum class GBDomainKind { RegularPolygon, AngleLength, Projection };

// Signed turning angle at the end of each face side (positive: a convex corner, a left turn
// around the loop's Newell normal).
std::vector<double> face_turning_angles(const FaceRibbons& ribbons);

// The ribbons with the cross-boundary fields of the sides at reflex corners turned into the
// face (see gb_face.cpp); G1 with the neighbouring faces is kept.
FaceRibbons orient_reflex_corners(const FaceRibbons& ribbons);

// The cubic ribbons (reflex corners re-oriented) as a GB patch (d_i = 3, l_i = 2). Throws
// std::invalid_argument if no domain gives a valid patch (e.g. a face so concave that mean value
// coordinates fail).
std::unique_ptr<GBRibbonPatch> gb_face_patch(const FaceRibbons& ribbons,
                                             GBDomainKind* used = nullptr);

// The ribbons the GB patch of a face is built from: the input for a convex face, the reflex
// corners oriented (orient_reflex_corners) otherwise.
FaceRibbons ribbons_as_filled(const FaceRibbons& ribbons);

}  // namespace pl
