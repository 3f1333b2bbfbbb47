// Mouse-driven camera moves on top of render/camera.hpp: a turntable orbit about any pivot (the
// scene centre or the selected point) that keeps the pivot where it is on screen, panning by
// pixels, zooming towards the cursor. GUI-free and unit-tested.
#pragma once

#include <span>

#include "app/editor/logic/view_math.hpp"

namespace pl {

// Radians of orbit per pixel of mouse motion.
constexpr double kOrbitRadiansPerPixel = 0.006;

// Turntable: yaw about the world z axis, pitch about the camera's right axis, both about pivot.
void orbit_about(Camera& camera, const Vec3& pivot, double dyaw, double dpitch);

// Where some points lie on screen: the box of their window pixels (points behind the eye left
// out); empty when none is in front of the eye.
struct ScreenBox {
  Vec2 lo{1e300}, hi{-1e300};
  bool empty() const { return lo.x > hi.x; }
};
ScreenBox screen_box(const Camera& camera, const ViewRect& rect, std::span<const Vec3> points);

// After an orbit step about a pivot other than the model's centre (the selection, say, at the
// edge of the view) the rest of the model swings around the pivot and can leave the view. This
// pans the view, when needed, so that on each axis the model's on-screen extent (`points`: a
// sample of it) is no further out of place than it was at `was` (its ScreenBox when the orbit
// began): a model that fitted in the view stays in it, one seen larger than the view stays
// centred on it. The pivot stays put whenever the model allows.
void keep_in_view(Camera& camera, const ViewRect& rect, std::span<const Vec3> points,
                  const ScreenBox& was);

// Moves the view so the scene follows the cursor by (dx, dy) pixels at the target's depth.
void pan_pixels(Camera& camera, const ViewRect& rect, double dx, double dy);

// Zooms by `factor` (> 1: closer) keeping the point under `pixel` on the target plane fixed.
void zoom_at(Camera& camera, const ViewRect& rect, const Vec2& pixel, double factor);

}  // namespace pl
