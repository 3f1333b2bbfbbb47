// Constrained Delaunay triangulation of a simple polygon with extra interior points: the
// boundary edges are kept, every other edge is locally Delaunay (well-shaped triangles).
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "core/math/vec.hpp"

namespace pl {

// points[0 .. boundary_count) is the polygon, counter-clockwise, simple; `corners` (ascending)
// are the indices of its true vertices, the boundary points between two corners lie on their
// segment (given, not detected: rounded side samples are never exactly collinear). The
// remaining points lie strictly inside. Returns counter-clockwise
// triangles covering the polygon exactly once. An interior point that falls exactly on an
// existing edge splits it; one that coincides with a vertex or lies on the boundary is skipped;
// `used` (if given) reports which points are referenced. Throws std::invalid_argument if the
// polygon cannot be ear-clipped.
std::vector<std::array<uint32_t, 3>> triangulate_polygon(std::span<const Vec2> points,
                                                         std::size_t boundary_count,
                                                         const std::vector<uint32_t>& corners,
                                                         std::vector<bool>* used = nullptr);

}  // namespace pl
