// The view camera: orbit/pan/zoom about a target, presets, framing a bounding box. Pure maths,
// no OpenGL, so it is unit-tested and shared by the CLI renderer and the future editor.
//
// World is z-up. The eye sits at target + distance * d(yaw, pitch) with
//   d = (cos pitch cos yaw, cos pitch sin yaw, sin pitch),
// so yaw = -90 deg, pitch = 0 looks from -y (front), and pitch = +90 deg looks down (top).
#pragma once

#include <array>
#include <optional>
#include <span>
#include <string>

#include "core/math/vec.hpp"

namespace pl {

struct Box {
  Vec3 lo{1e300}, hi{-1e300};
  bool empty() const { return lo.x > hi.x; }
  void add(const Vec3& p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  Vec3 centre() const { return 0.5 * (lo + hi); }
  double radius() const { return 0.5 * glm::length(hi - lo); }  // of the bounding sphere
};

enum class ViewPreset { Iso, Front, Back, Left, Right, Top, Bottom };
// "iso", "front", ...; nullopt for anything else.
std::optional<ViewPreset> parse_view_preset(const std::string& name);

struct Camera {
  Vec3 target{0.0};
  double distance = 5;        // eye to target, > 0
  double yaw = 0;             // radians
  double pitch = 0;           // radians, clamped to [-pi/2, pi/2]
  double fov_y = 0.5236;      // vertical field of view in radians (perspective)
  bool orthographic = false;  // then the view height at the target is 2 distance tan(fov_y/2)

  Vec3 eye() const;
  Vec3 forward() const;  // unit, from the eye towards the target
  Vec3 up() const;       // unit, orthogonal to forward; never degenerate (also at the poles)
  Vec3 right() const;    // unit, forward x up
  glm::dmat4 view() const;
  // near/far are chosen from the framed scene radius (see frame()).
  glm::dmat4 projection(double aspect) const;
  // The near and far clipping distances along the view direction from the eye.
  std::array<double, 2> clip_planes() const;
  // Half the visible height in world units at the target distance.
  double half_height() const;

  // Mouse-style interaction. Angles in radians; pan in world units along right/up; zoom > 1
  // moves closer (distance / factor).
  void orbit(double dyaw, double dpitch);
  void pan(double dx, double dy);
  void zoom(double factor);

  // Aims at the box centre from the current direction and sets the distance so the box's eight
  // corners, scaled about the centre by `margin` (>= 1), are inside the view at this aspect
  // (width / height).
  void frame(const Box& box, double aspect, double margin = 1.08);
  // The same for a set of points, fitted tightly: aims at the middle of their extent across the
  // view (not the box centre) and takes the distance at which the farthest-out point touches the
  // view's edge. A thin patch seen obliquely fills the view instead of its bounding box's corners.
  void frame_points(std::span<const Vec3> points, double aspect, double margin = 1.08);

  double scene_radius = 1;  // set by frame(); sizes the clipping planes
};

Camera preset_camera(ViewPreset preset, const Box& box, double aspect, bool orthographic = false);

}  // namespace pl
