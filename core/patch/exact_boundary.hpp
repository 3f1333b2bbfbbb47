// Whether a patch's boundary_curves() are its sides exactly (each side is the one Bézier curve
// returned for it, at the same parameter), as opposed to a curve that only shares the side's end
// points (multi-span spline sides, piecewise composite sides, subdivision limits). CAD export
// takes exact sides as the piece's edges; the others are fitted.
#pragma once

#include "core/patch/patch.hpp"

namespace pl {

// One answer per registered type (patch_types.hpp); a ribbons patch answers per instance (its
// sides are Bézier curves or not, by the curves it was given).
bool boundary_curves_are_exact(const Patch& patch);

}  // namespace pl
