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

namespace {

// How far p is outside the interval [lo, hi] (0 inside), signed: < 0 below, > 0 above.
double outside(double p, double lo, double hi) {
  return p < lo ? p - lo : p > hi ? p - hi : 0.0;
}

}  // namespace

void keep_in_view(Camera& c, const ViewRect& r, const Vec3& centre, const Vec2& was) {
  const auto now = project_to_window(c, r, centre);
  if (!now) return;  // behind the eye: an orbit about a point cannot put it there for long
  const double mx = r.x + 0.5 * r.width, my = r.y + 0.5 * r.height;
  const double hx = kKeepInView * 0.5 * r.width, hy = kKeepInView * 0.5 * r.height;
  // Per axis: the overshoot now, allowed as far as it was before the step.
  auto correction = [](double now, double was, double lo, double hi) {
    const double o = outside(now, lo, hi), allowed = outside(was, lo, hi);
    if (o == 0 || (o < 0 && allowed < 0 && o >= allowed) || (o > 0 && allowed > 0 && o <= allowed))
      return 0.0;
    const double limit = (o < 0) == (allowed < 0) ? allowed : 0.0;
    return limit - o;  // the screen shift that brings it back to its limit
  };
  const double sx = correction(now->x, was.x, mx - hx, mx + hx);
  const double sy = correction(now->y, was.y, my - hy, my + hy);
  if (sx == 0 && sy == 0) return;
  // A pan translates eye and target: the centre keeps its depth, so the shift is exact.
  const double w = world_per_pixel(c, r, centre);
  c.pan(-sx * w, sy * w);
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
