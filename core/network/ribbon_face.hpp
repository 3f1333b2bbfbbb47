// Network faces filled by the ribbon-based transfinite schemes (core/patch/transfinite): the
// face's Chiyokura-Kimura ribbons (face_ribbons.hpp) become explicit ribbons, P_i the edge cubic
// and D_i(t) = 3 (inner(t) - boundary(t)) the cubic cross-boundary derivative of the same data
// the Gregory and GB faces use, so every scheme meets its neighbours with the same tangent
// planes (G1). The domain is the regular n-gon for every scheme (as for convex GB faces: a
// comparison differs in the blending and parameterization only). Face side i becomes domain side
// i, traversed the same way with the same parameter.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "core/network/face_ribbons.hpp"
#include "core/patch/transfinite/ribbon_patch.hpp"

namespace pl {

// The ribbons of a face as explicit Bézier ribbons, side i in loop order.
std::vector<RibbonSide> explicit_ribbons(const FaceRibbons& ribbons);

// The face filled by `scheme`. Throws std::invalid_argument for a concave face (naming the loop
// position of its reflex corner): the schemes' parameterizations need a convex domain, and the
// regular n-gon over a concave boundary would fold.
// fullness: the midpoint schemes' setting (RibbonPatchOptions::fullness), ignored by the others.
std::unique_ptr<RibbonPatch> ribbon_face_patch(const FaceRibbons& ribbons,
                                               transfinite::RibbonScheme scheme,
                                               double fullness = 1);

}  // namespace pl
