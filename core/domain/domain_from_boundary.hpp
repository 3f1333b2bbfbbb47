// Parameter domains for n-sided faces from their 3D boundary (SMI 2018, section "Domain
// generation"): projection of the corners to the least-squares plane, or the angle + arc-length
// heuristic that keeps the boundary's turning angles and edge lengths for curved faces.
#pragma once

#include <optional>
#include <vector>

#include "core/math/vec.hpp"

namespace pl {

// Corners projected to their best-fit plane (Eigen: smallest eigenvector of the covariance),
// with the plane's in-plane axes oriented so that the polygon's Newell normal (the right-hand
// normal of the loop) points out of the (u, v) plane: a loop counter-clockwise around its
// normal gives a counter-clockwise domain. Rescaled to fit [-1, 1]^2. Throws
// std::invalid_argument for fewer than 3 points or a degenerate (collinear) loop.
std::vector<Vec2> project_to_best_fit_plane(const std::vector<Vec3>& corners);

// The heuristic: an open polygon with the given edge lengths and turning angles (signed,
// positive = convex corner of a counter-clockwise loop; angle k is the turn at the end of edge
// k) after the angles are scaled to sum to 2 pi, closed by distributing the gap along the
// edges in proportion to arc length, rescaled to fit [-1, 1]^2. Vertex k is the end of edge k.
// Returns nothing if the angles cannot be normalised (their sum is not positive).
std::optional<std::vector<Vec2>> angle_length_domain(const std::vector<double>& lengths,
                                                     const std::vector<double>& turning);

// Translates and uniformly scales points to fit [-1, 1]^2, centred.
void fit_unit_box(std::vector<Vec2>& points);

}  // namespace pl
