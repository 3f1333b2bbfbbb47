// The curve a patch traces along one side of its domain, with exact derivatives taken from the
// surface jet: x(t) = a + t (b - a) on the side, so C'(t) = J (b - a) and
// C''(t) = (b - a)^T H (b - a). Exact for every patch type (multi-span spline sides, composite
// and subdivision pieces, GB and Gregory patches) because it uses evaluate() itself rather than
// boundary_curves(), which some types only approximate.
#pragma once

#include "core/curve/curvature_comb.hpp"
#include "core/patch/patch.hpp"

namespace pl {

// Side parameter t in [0, 1] from the side's start vertex, as Domain::side_point. At the end
// vertices (t = 0, 1) C'' is the limit along the side, extrapolated from just inside it.
CurvePoint side_curve_point(const Patch& patch, int side, double t);

// The curvature comb of side `side` (see curvature_comb), its points on the exact surface.
CurvatureComb side_comb(const Patch& patch, int side, int teeth);
// One per domain side, in side order: what a border overlay draws (its points are the border).
std::vector<CurvatureComb> side_combs(const Patch& patch, int teeth);
// The points alone, at t = k / segments (the points of a comb with as many samples, without its
// end extrapolation and teeth): a border drawn without a comb. Throws std::invalid_argument
// unless segments >= 1.
std::vector<Vec3> side_polyline(const Patch& patch, int side, int segments);

}  // namespace pl
