#include "app/editor/logic/camera_control.hpp"

namespace pl {

void orbit_about(Camera& c, const Vec3& pivot, double dyaw, double dpitch) {
  // The pivot's coordinates in the camera frame are kept, so it stays put on screen.
  const Vec3 eye = c.eye();
  const Vec3 rel = pivot - eye;
  const double a = glm::dot(rel, c.right()), b = glm::dot(rel, c.up()),
               d = glm::dot(rel, c.forward());
  c.orbit(dyaw, dpitch);
  const Vec3 new_eye = pivot - a * c.right() - b * c.up() - d * c.forward();
  c.target = new_eye + c.distance * c.forward();
}

void pan_pixels(Camera& c, const ViewRect& r, double dx, double dy) {
  const double s = 2 * c.half_height() / r.height;
  // Dragging right moves the scene right, so the camera moves left; window y grows downwards.
  c.pan(-dx * s, dy * s);
}

void zoom_at(Camera& c, const ViewRect& r, const Vec2& pixel, double factor) {
  if (!(factor > 0)) return;
  const Ray ray = window_ray(c, r, pixel);
  const auto q = intersect_plane(ray, c.target, c.forward());
  c.zoom(factor);
  if (q) c.target = *q - (*q - c.target) / factor;
}

}  // namespace pl
