// Splits a patch's polygonal parameter domain into convex quadrilaterals, each the domain of
// one four-sided surface piece (bilinearly mapped from the unit square). A convex quadrilateral
// stays whole; any other convex polygon is split centrally (corner i: vertex i, the midpoint of
// the side leaving it, the centroid, the midpoint of the side arriving), after a ring of two
// pieces per side (between the side and the polygon shrunk halfway to the centroid) where a
// corner exceeds 150 degrees (13 sides and more), so that no piece has a corner that flat; a
// concave polygon is first cut from each reflex vertex along its angle bisector to the boundary,
// and every convex part is then split centrally, so that parts sharing a cut also share its
// midpoint.
#pragma once

#include <array>
#include <vector>

#include "core/domain/domain.hpp"

namespace pl {

// Corners c00, c10, c11, c01 (counter-clockwise): x(u, v) = bilinear blend of them.
using DomainQuad = std::array<Vec2, 4>;

// The polygon of a domain: vertex s = side_point(s, 0), side s from vertex s to vertex s + 1.
std::vector<Vec2> domain_polygon(const Domain& domain);

// Throws std::invalid_argument if the polygon is not simple and counter-clockwise enough to be
// split into strictly convex quadrilaterals this way.
std::vector<DomainQuad> split_into_quads(const std::vector<Vec2>& polygon);

// x(u, v) and its derivatives for a quad.
Vec2 quad_point(const DomainQuad& q, Vec2 uv);
Vec2 quad_du(const DomainQuad& q, Vec2 uv);
Vec2 quad_dv(const DomainQuad& q, Vec2 uv);

}  // namespace pl
