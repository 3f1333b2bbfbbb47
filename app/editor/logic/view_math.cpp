#include "app/editor/logic/view_math.hpp"

#include <cmath>
#include <limits>

namespace pl {

namespace {
// Screen distances closer than this (pixels) count as the same spot when picking.
constexpr double kSamePixel = 0.5;
}  // namespace

WindowProjector::WindowProjector(const Camera& c, const ViewRect& r)
    : view_projection_(c.projection(r.aspect()) * c.view()), rect_(r) {}

std::optional<Vec2> WindowProjector::operator()(const Vec3& p) const {
  const glm::dvec4 clip = view_projection_ * glm::dvec4(p, 1.0);
  if (clip.w <= 0) return std::nullopt;
  const double nx = clip.x / clip.w, ny = clip.y / clip.w;
  return Vec2(rect_.x + (nx + 1) * 0.5 * rect_.width, rect_.y + (1 - ny) * 0.5 * rect_.height);
}

std::optional<Vec2> project_to_window(const Camera& c, const ViewRect& r, const Vec3& p) {
  return WindowProjector(c, r)(p);
}

Ray window_ray(const Camera& c, const ViewRect& r, const Vec2& pixel) {
  // Normalised device offsets scaled to the half extents of the view at the target distance.
  const double nx = 2 * (pixel.x - r.x) / r.width - 1;
  const double ny = 1 - 2 * (pixel.y - r.y) / r.height;
  const double h = c.half_height(), w = h * r.aspect();
  const Vec3 on_target_plane = c.target + nx * w * c.right() + ny * h * c.up();
  if (c.orthographic) {
    // Start well behind the scene so every visible surface is in front of the origin.
    const double back = c.distance + 4 * c.scene_radius;
    return {on_target_plane - back * c.forward(), c.forward()};
  }
  const Vec3 eye = c.eye();
  return {eye, glm::normalize(on_target_plane - eye)};
}

void NearestPoint::offer(int i, double d, double z) {
  if (d < distance - kSamePixel || (d <= distance + kSamePixel && z < depth)) {
    index = i;
    distance = d;
    depth = z;
  }
}

int pick_point(const Camera& c, const ViewRect& r, std::span<const Vec3> points,
               const std::vector<bool>& pickable, const Vec2& pixel, double radius) {
  NearestPoint best;
  const Vec3 eye = c.eye(), f = c.forward();
  const WindowProjector project(c, r);
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!pickable.empty() && !pickable[i]) continue;
    const auto s = project(points[i]);
    if (!s) continue;
    const double d = glm::length(*s - pixel);
    if (d <= radius) best.offer(static_cast<int>(i), d, glm::dot(points[i] - eye, f));
  }
  return best.index;
}

std::optional<Vec3> intersect_plane(const Ray& ray, const Vec3& point, const Vec3& normal) {
  const double denom = glm::dot(ray.direction, normal);
  if (std::abs(denom) < 1e-12) return std::nullopt;
  const double t = glm::dot(point - ray.origin, normal) / denom;
  return ray.origin + t * ray.direction;
}

Vec3 closest_on_axis(const Ray& ray, const Vec3& origin, const Vec3& axis) {
  // Minimise |origin + s axis - (ray.origin + t dir)| over s, t.
  const Vec3 w = origin - ray.origin;
  const double b = glm::dot(axis, ray.direction);
  const double d = glm::dot(axis, w), e = glm::dot(ray.direction, w);
  const double denom = 1 - b * b;
  if (denom < 1e-12) return origin;  // the axis points at the eye: no motion along it is visible
  const double s = (b * e - d) / denom;
  return origin + s * axis;
}

Vec3 DragMotion::offset(const Camera& c, const ViewRect& r, const Vec2& pixel,
                        const std::optional<Vec3>& axis) const {
  const Ray now = window_ray(c, r, pixel), then = window_ray(c, r, start_pixel);
  if (axis) return closest_on_axis(now, start, *axis) - closest_on_axis(then, start, *axis);
  const auto a = intersect_plane(now, start, c.forward());
  const auto b = intersect_plane(then, start, c.forward());
  if (!a || !b) return Vec3(0);
  return *a - *b;
}

double world_per_pixel(const Camera& c, const ViewRect& r, const Vec3& p) {
  const double depth = c.orthographic ? c.distance : glm::dot(p - c.eye(), c.forward());
  return 2 * depth * std::tan(0.5 * c.fov_y) / r.height;
}

}  // namespace pl
