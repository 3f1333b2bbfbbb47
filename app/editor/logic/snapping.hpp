// Where a new point snaps when snapping is on (WorkPlane::snap; Alt held suspends it): onto the
// scene's points near the cursor (within a radius in pixels), else onto the work plane's grid.
// Candidates, the nearer on screen winning and points before curves: network vertices, free-curve
// control points, the ends and midpoints of edges and free curves (midpoint: the middle of the
// parameter range), and the nearest point of an edge or free curve to the cursor (found on
// samples, then refined on the curve itself). GUI-free.
#pragma once

#include <optional>
#include <string>

#include "app/editor/logic/view_math.hpp"
#include "app/editor/logic/work_plane.hpp"
#include "core/scene/scene.hpp"

namespace pl {

enum class SnapKind { Vertex, CurvePoint, End, Midpoint, OnCurve, Grid };

struct Snapped {
  Vec3 point{0.0};
  SnapKind kind = SnapKind::Grid;
  std::string what;  // "vertex 3", "curve 1 point 2", "edge 4 end", "curve 0 midpoint", "grid"
  int vertex = -1;   // SnapKind::Vertex: which
};

// The snap for the cursor at `pixel` within `radius` pixels, if any (no grid: see
// snap_to_grid). Points behind the eye are not candidates.
std::optional<Snapped> snap_to_scene(const Scene& scene, const Camera& camera, const ViewRect& rect,
                                     const Vec2& pixel, double radius);

// The grid point of the shown grid nearest to where the cursor's ray meets the work plane.
std::optional<Snapped> snap_to_grid(const WorkPlane& plane, const Camera& camera,
                                    const ViewRect& rect, const Vec2& pixel);

}  // namespace pl
