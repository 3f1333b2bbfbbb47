#include "app/editor/logic/camera_control.hpp"

#include <algorithm>
#include <cmath>

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

ScreenBox screen_box(const Camera& c, const ViewRect& r, std::span<const Vec3> points) {
  ScreenBox b;
  const WindowProjector project(c, r);
  for (const Vec3& p : points)
    if (const auto w = project(p)) {
      b.lo = glm::min(b.lo, *w);
      b.hi = glm::max(b.hi, *w);
    }
  return b;
}

namespace {

// How far p is outside [-a, a] (0 inside), signed.
double outside(double p, double a) {
  return p < -a ? p + a : p > a ? p - a : 0.0;
}

// The screen shift along one axis that brings the model back to where it may be. Its middle
// may sit up to a = (view - model) / 2 from the view's middle, so that it stays inside the view;
// a model wider than the view stays centred, as much of it shown as can be. How far out of place
// it was when the orbit began (`start`, measured the same way) is allowed too, on that side.
double correction(double view_lo, double view_hi, double lo, double hi, double start_lo,
                  double start_hi) {
  const double view = view_hi - view_lo, mid = 0.5 * (view_lo + view_hi);
  auto room = [&](double l, double h) { return std::max(0.0, 0.5 * (view - (h - l))); };
  const double was = outside(0.5 * (start_lo + start_hi) - mid, room(start_lo, start_hi));
  const double a = room(lo, hi), o = 0.5 * (lo + hi) - mid;
  const double low = -a + std::min(0.0, was), high = a + std::max(0.0, was);
  return o < low ? low - o : o > high ? high - o : 0.0;
}

}  // namespace

void keep_in_view(Camera& c, const ViewRect& r, std::span<const Vec3> points,
                  const ScreenBox& was) {
  if (was.empty() || points.empty()) return;
  Vec3 centroid(0);
  for (const Vec3& p : points) centroid += p;
  centroid /= double(points.size());
  // A pan moves points at other depths by other amounts in perspective: a few rounds settle it.
  for (int round = 0; round < 3; ++round) {
    const ScreenBox now = screen_box(c, r, points);
    if (now.empty()) return;
    const double sx = correction(r.x, r.x + r.width, now.lo.x, now.hi.x, was.lo.x, was.hi.x);
    const double sy = correction(r.y, r.y + r.height, now.lo.y, now.hi.y, was.lo.y, was.hi.y);
    if (std::abs(sx) < 0.25 && std::abs(sy) < 0.25) return;
    const double w = world_per_pixel(c, r, centroid);
    c.pan(-sx * w, sy * w);
  }
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
