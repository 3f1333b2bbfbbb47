// The domain polygon of the side-based scheme, built from the boundary curves (Salvi, Varady,
// Rockwood, "Ribbon-based transfinite surfaces", CAGD 31 (2014), section 3.1, as the authors'
// research library transfinite builds it, "DomainAngular"): side i as long as the arc length of
// P_i, the angle at corner i proportional to the angle between the curves there (scaled so that
// the angles sum to (n - 2) pi), the open chain closed by spreading its gap over the vertices in
// proportion to arc length, then moved and scaled into [-1, 1]^2.
#pragma once

#include <optional>
#include <vector>

#include "core/math/vec.hpp"
#include "core/patch/transfinite/ribbon_set.hpp"

namespace pl::transfinite {

// The vertices v_0 ... v_{n-1} (v_i the image of corner i, the end of side i), counter-clockwise;
// none when the polygon comes out degenerate or not strictly convex (the caller then takes the
// regular n-gon, as the library falls back to a circle).
std::optional<std::vector<Vec2>> angular_domain(const std::vector<RibbonCurves>& sides);

// The library's centre of such a polygon: the vertices weighted by the lengths of their two
// sides, sum_i v_i (l_i + l_{i+1}) / (2 sum_i l_i), l_i = |v_i - v_{i-1}|.
Vec2 angular_domain_centre(const std::vector<Vec2>& v);

}  // namespace pl::transfinite
