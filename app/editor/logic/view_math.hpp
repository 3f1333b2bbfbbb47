// Screen <-> world maths of the editor's viewport: projecting points to window pixels, the ray
// under the cursor, picking the nearest control point and turning mouse motion into point
// motion (in the view plane or along an axis). Window pixels have their origin at the top left,
// like GLFW's cursor positions. GUI-free and unit-tested.
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "render/camera.hpp"

namespace pl {

struct ViewRect {
  double x = 0, y = 0, width = 1, height = 1;  // window pixels, top-left origin
  double aspect() const { return width / height; }
  bool contains(const Vec2& p) const {
    return p.x >= x && p.y >= y && p.x < x + width && p.y < y + height;
  }
};

struct Ray {
  Vec3 origin, direction;  // direction unit
};

// Window pixel of p; nullopt behind the eye.
std::optional<Vec2> project_to_window(const Camera& camera, const ViewRect& rect, const Vec3& p);

// project_to_window for many points: the camera's matrices are formed once.
class WindowProjector {
 public:
  WindowProjector(const Camera& camera, const ViewRect& rect);
  std::optional<Vec2> operator()(const Vec3& p) const;

 private:
  glm::dmat4 view_projection_;
  ViewRect rect_;
};

// The ray through a window pixel (perspective: from the eye; orthographic: parallel).
Ray window_ray(const Camera& camera, const ViewRect& rect, const Vec2& pixel);

// The best of the points offered for picking: nearest on screen; points on (nearly) the same
// pixel are told apart by depth, nearest to the eye first (the one drawn on top).
struct NearestPoint {
  int index = -1;
  double distance = 1e300, depth = 1e300;  // pixels from the cursor; along the view
  void offer(int i, double d, double z);
};

// Index of the point nearest to `pixel` within `radius` pixels; among points on the same spot,
// the one nearest the eye. `pickable[i]` false skips a point (empty span:
// all pickable). -1 if none.
int pick_point(const Camera& camera, const ViewRect& rect, std::span<const Vec3> points,
               const std::vector<bool>& pickable, const Vec2& pixel, double radius);

// Where the ray meets the plane through `point` with normal `normal`; nullopt if parallel.
std::optional<Vec3> intersect_plane(const Ray& ray, const Vec3& point, const Vec3& normal);

// The point of the line origin + t axis closest to the ray.
Vec3 closest_on_axis(const Ray& ray, const Vec3& origin, const Vec3& axis);

// A drag: the grabbed point's start position and the cursor's start pixel. The moved point
// follows the cursor in the plane through the start position facing the camera, or along
// `axis` (unit) when one is given.
struct DragMotion {
  Vec3 start;
  Vec2 start_pixel;
  // Translation to apply to every dragged point for the cursor at `pixel`.
  Vec3 offset(const Camera& camera, const ViewRect& rect, const Vec2& pixel,
              const std::optional<Vec3>& axis) const;
};

// World units per window pixel at the depth of `p` (the view-plane drag scale).
double world_per_pixel(const Camera& camera, const ViewRect& rect, const Vec3& p);

}  // namespace pl
