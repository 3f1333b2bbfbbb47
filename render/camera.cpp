#include "render/camera.hpp"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace pl {

namespace {
constexpr double kHalfPi = 1.5707963267948966;
}

std::optional<ViewPreset> parse_view_preset(const std::string& name) {
  if (name == "iso") return ViewPreset::Iso;
  if (name == "front") return ViewPreset::Front;
  if (name == "back") return ViewPreset::Back;
  if (name == "left") return ViewPreset::Left;
  if (name == "right") return ViewPreset::Right;
  if (name == "top") return ViewPreset::Top;
  if (name == "bottom") return ViewPreset::Bottom;
  return std::nullopt;
}

Vec3 Camera::forward() const {
  const Vec3 d(std::cos(pitch) * std::cos(yaw), std::cos(pitch) * std::sin(yaw), std::sin(pitch));
  return -d;
}

// d/dpitch of the eye direction: orthogonal to it and defined at the poles, where "z-up" is not.
Vec3 Camera::up() const {
  return Vec3(-std::sin(pitch) * std::cos(yaw), -std::sin(pitch) * std::sin(yaw), std::cos(pitch));
}

Vec3 Camera::right() const {
  return glm::cross(forward(), up());
}

Vec3 Camera::eye() const {
  return target - distance * forward();
}

glm::dmat4 Camera::view() const {
  return glm::lookAt(eye(), target, up());
}

double Camera::half_height() const {
  return distance * std::tan(0.5 * fov_y);
}

std::array<double, 2> Camera::clip_planes() const {
  // Clip planes hug the framed scene so depth precision stays good at any scale.
  const double r = std::max(scene_radius, 1e-9);
  const double far_plane = distance + 2 * r;
  if (orthographic) return {std::max(distance - 2 * r, -far_plane), far_plane};
  return {std::max(distance - 2 * r, far_plane * 1e-4), far_plane};
}

glm::dmat4 Camera::projection(double aspect) const {
  const auto [near_plane, far_plane] = clip_planes();
  if (orthographic) {
    const double h = half_height();
    return glm::ortho(-h * aspect, h * aspect, -h, h, near_plane, far_plane);
  }
  return glm::perspective(fov_y, aspect, near_plane, far_plane);
}

void Camera::orbit(double dyaw, double dpitch) {
  yaw = std::remainder(yaw + dyaw, 4 * kHalfPi);
  pitch = std::clamp(pitch + dpitch, -kHalfPi, kHalfPi);
}

void Camera::pan(double dx, double dy) {
  target += dx * right() + dy * up();
}

void Camera::zoom(double factor) {
  if (factor > 0) distance /= factor;
}

void Camera::frame(const Box& box, double aspect, double margin) {
  if (box.empty()) return;
  target = box.centre();
  scene_radius = std::max(box.radius(), 1e-12);
  const double tan_v = std::tan(0.5 * fov_y), tan_h = tan_v * aspect;
  const Vec3 f = forward(), u = up(), r = right();
  // Fit the box's eight corners rather than its bounding sphere: flat parts fill the view.
  double need_h = 0, need_d = 0;
  for (int i = 0; i < 8; ++i) {
    const Vec3 c((i & 1) ? box.hi.x : box.lo.x, (i & 2) ? box.hi.y : box.lo.y,
                 (i & 4) ? box.hi.z : box.lo.z);
    const Vec3 q = (c - target) * margin;
    const double x = std::abs(glm::dot(q, r)), y = std::abs(glm::dot(q, u));
    const double z = glm::dot(q, f);  // > 0: beyond the target, seen smaller
    need_h = std::max({need_h, y, x / aspect});
    // Perspective: the corner is inside when x <= (distance + z) tan_h, likewise for y.
    need_d = std::max({need_d, x / tan_h - z, y / tan_v - z});
  }
  const double floor_d = 1e-6 * scene_radius;  // the eye never sits on the target
  distance = std::max(orthographic ? need_h / tan_v : need_d, floor_d);
  // Perspective: the eye must stay outside the box for the near plane to make sense.
  if (!orthographic) distance = std::max(distance, scene_radius * 1.05);
}

void Camera::frame_points(std::span<const Vec3> points, double aspect, double margin) {
  if (points.empty()) return;
  Box box;
  for (const Vec3& p : points) box.add(p);
  if (!(box.radius() > 1e-9 * (1 + glm::length(box.centre())))) {
    // Everything at one place (a collapsed patch): show that place in a unit box.
    const Vec3 c = box.centre();
    box.add(c - Vec3(1.0));
    box.add(c + Vec3(1.0));
    frame(box, aspect, margin);
    return;
  }
  scene_radius = box.radius();
  const Vec3 f = forward(), u = up(), r = right();
  // The middle of the extent along right and up, and along the view for the clipping planes.
  double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
  for (const Vec3& p : points) {
    const double c[3] = {glm::dot(p, r), glm::dot(p, u), glm::dot(p, f)};
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], c[k]), hi[k] = std::max(hi[k], c[k]);
  }
  target = 0.5 * ((lo[0] + hi[0]) * r + (lo[1] + hi[1]) * u + (lo[2] + hi[2]) * f);
  const double tan_v = std::tan(0.5 * fov_y), tan_h = tan_v * aspect;
  double need_h = 0, need_d = 0;
  for (const Vec3& p : points) {
    const Vec3 q = (p - target) * margin;
    const double x = std::abs(glm::dot(q, r)), y = std::abs(glm::dot(q, u));
    const double z = glm::dot(q, f);  // > 0: beyond the target, seen smaller
    need_h = std::max({need_h, y, x / aspect});
    need_d = std::max({need_d, x / tan_h - z, y / tan_v - z});
  }
  const double floor_d = 1e-6 * scene_radius;
  distance = std::max(orthographic ? need_h / tan_v : need_d, floor_d);
  // Perspective: the eye stays in front of every point.
  if (!orthographic) distance = std::max(distance, 0.5 * (hi[2] - lo[2]) * 1.05 + floor_d);
  // The clipping planes must enclose the points around the new target.
  for (const Vec3& p : points) scene_radius = std::max(scene_radius, glm::length(p - target));
}

Camera preset_camera(ViewPreset preset, const Box& box, double aspect, bool orthographic) {
  Camera c;
  c.orthographic = orthographic;
  switch (preset) {
    case ViewPreset::Iso:
      c.yaw = -0.5 * kHalfPi;                   // from the (+x, -y) quadrant
      c.pitch = std::atan(1 / std::sqrt(2.0));  // the cube-diagonal elevation, 35.26 deg
      break;
    case ViewPreset::Front:
      c.yaw = -kHalfPi;
      break;
    case ViewPreset::Back:
      c.yaw = kHalfPi;
      break;
    case ViewPreset::Left:
      c.yaw = 2 * kHalfPi;
      break;
    case ViewPreset::Right:
      c.yaw = 0;
      break;
    case ViewPreset::Top:
      c.yaw = -kHalfPi;
      c.pitch = kHalfPi;
      break;
    case ViewPreset::Bottom:
      c.yaw = -kHalfPi;
      c.pitch = -kHalfPi;
      break;
  }
  c.frame(box, aspect);
  return c;
}

}  // namespace pl
