// The work plane: where a click in empty space lands when a tool places something (a new
// vertex, a curve point). Either facing the camera or one of the world planes XY / XZ / YZ, in
// every case through a chosen origin (the scene centre, a picked point, typed coordinates).
// It is drawn as a grid whose spacing follows the zoom (1-2-5 steps) and whose centre follows
// the view, so some of it is always under the cursor. GUI-free and unit-tested.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "app/editor/logic/view_math.hpp"

namespace pl {

enum class WorkPlaneKind { View, XY, XZ, YZ };
const char* work_plane_name(WorkPlaneKind kind);  // "View", "XY", "XZ", "YZ"

// A plane with an orthonormal frame: u x v = normal.
struct PlaneFrame {
  Vec3 origin{0.0}, normal{0, 0, 1}, u{1, 0, 0}, v{0, 1, 0};
};

struct WorkPlane {
  // The ground plane by default (the world is z-up), as CAD tools start.
  WorkPlaneKind kind = WorkPlaneKind::XY;
  Vec3 origin{0.0};
  bool shown = false;  // the grid is drawn
  // New points snap (snapping.hpp): to vertices, curve points, ends and midpoints, onto curves,
  // and on the plane to the grid shown (Alt held suspends it).
  bool snap = false;

  // The plane for this camera (a view-aligned plane turns with it: normal towards the eye, u
  // right, v up; world planes keep their axes, normals +z, +y flipped to -y for XZ so that u x v
  // = normal with u = +x, v = +z, and +x for YZ).
  PlaneFrame frame(const Camera& camera) const;
  // Where the ray meets the plane, in front of the ray origin; nullopt when the ray is parallel
  // to the plane or meets it behind.
  std::optional<Vec3> hit(const Camera& camera, const Ray& ray) const;
};

// The ray-plane intersection in front of the origin (t > 0), or nullopt.
std::optional<Vec3> intersect_plane_ahead(const Ray& ray, const PlaneFrame& plane);

// The nice grid step (1, 2 or 5 times a power of ten) closest above `world_size / cells`.
double grid_step(double world_size, int cells);
// About this many grid cells span the view's height.
inline constexpr int kGridCellsPerView = 12;
// The step of the grid drawn for this camera (what grid snapping rounds to).
double shown_grid_step(const Camera& camera);
// p (on the plane) moved to the nearest grid point: multiples of `step` from the origin along u
// and v.
Vec3 nearest_grid_point(const PlaneFrame& frame, const Vec3& p, double step);

// Grid lines of `frame` as segment end points (pairs, one per cell side), `2 * half_cells` cells
// of `step` across, centred on the grid point nearest to `centre` projected onto the plane
// (lines stay on multiples of the step from the origin, so the grid does not swim as the view
// moves).
std::vector<Vec3> grid_segments(const PlaneFrame& frame, const Vec3& centre, double step,
                                int half_cells);

// Coordinates of p in the plane's frame (u, v): what the status bar shows.
Vec2 plane_coordinates(const PlaneFrame& frame, const Vec3& p);

}  // namespace pl
