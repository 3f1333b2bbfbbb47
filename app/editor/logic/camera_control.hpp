// Mouse-driven camera moves on top of render/camera.hpp: a turntable orbit about any pivot (the
// scene centre or the selected point) that keeps the pivot where it is on screen, panning by
// pixels, zooming towards the cursor. GUI-free and unit-tested.
#pragma once

#include "app/editor/logic/view_math.hpp"

namespace pl {

// Radians of orbit per pixel of mouse motion.
constexpr double kOrbitRadiansPerPixel = 0.006;

// Turntable: yaw about the world z axis, pitch about the camera's right axis, both about pivot.
void orbit_about(Camera& camera, const Vec3& pivot, double dyaw, double dpitch);

// How far from the middle of the view the scene's centre may be moved by an orbit, as a fraction
// of the half width and half height: the model stays on screen around its centre.
constexpr double kKeepInView = 0.6;

// After an orbit step about a pivot other than the scene's centre (the selection, say, near
// the edge of the view), the rest of the model swings around it and can leave the view. This
// pans the view, when needed, so that `centre` is no further outside the middle part of the view
// (kKeepInView) than it was at `was` (its window pixel before the step): a centre inside stays
// inside, one outside is not pushed further out. The pivot stays put whenever it can.
void keep_in_view(Camera& camera, const ViewRect& rect, const Vec3& centre, const Vec2& was);

// Moves the view so the scene follows the cursor by (dx, dy) pixels at the target's depth.
void pan_pixels(Camera& camera, const ViewRect& rect, double dx, double dy);

// Zooms by `factor` (> 1: closer) keeping the point under `pixel` on the target plane fixed.
void zoom_at(Camera& camera, const ViewRect& rect, const Vec2& pixel, double factor);

}  // namespace pl
