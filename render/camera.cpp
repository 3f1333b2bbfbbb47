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

glm::dmat4 Camera::projection(double aspect) const {
  // Clip planes hug the framed scene so depth precision stays good at any scale.
  const double r = std::max(scene_radius, 1e-9);
  const double far_plane = distance + 2 * r;
  if (orthographic) {
    const double h = half_height();
    return glm::ortho(-h * aspect, h * aspect, -h, h, std::max(distance - 2 * r, -far_plane),
                      far_plane);
  }
  const double near_plane = std::max(distance - 2 * r, far_plane * 1e-4);
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
  const double r = scene_radius * margin;
  // The sphere must fit the narrower of the two field-of-view angles.
  const double half_v = 0.5 * fov_y;
  const double half_h = std::atan(std::tan(half_v) * aspect);
  const double half = std::min(half_v, half_h);
  // Perspective: the sphere is tangent to the narrower view cone. Orthographic: the half height
  // distance tan(half_v) must cover r vertically and r / aspect horizontally.
  distance = orthographic ? r / std::min(1.0, aspect) / std::tan(half_v) : r / std::sin(half);
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
