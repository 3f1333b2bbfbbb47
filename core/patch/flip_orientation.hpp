// Flipping a patch's orientation: the same surface with its normal S_u x S_v reversed, so the
// side shown as the front becomes the back. It is a re-parameterisation by a reflection of the
// domain (u <-> v for the square and triangle patches, a mirror symmetry of the polygon for GB
// patches, reversed face loops for Catmull–Clark), so every supported type gets exactly a
// permutation of its control points: the surface is unchanged point for point.
#pragma once

#include <memory>
#include <vector>

#include "core/patch/patch.hpp"

namespace pl {

struct FlippedPatch {
  std::unique_ptr<Patch> patch;
  // old_index[k]: the original index of the flipped patch's control point k (a selection or a
  // point reference follows the flip through it).
  std::vector<std::size_t> old_index;
};

// Whether flipped_orientation supports this patch's type (composite pair-join and gap-fill
// patches are not: their construction fixes which piece lies on which side).
bool can_flip_orientation(const Patch& patch);

// Throws std::invalid_argument naming the type when !can_flip_orientation(patch).
FlippedPatch flipped_orientation(const Patch& patch);

}  // namespace pl
