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

// Moves the view so the scene follows the cursor by (dx, dy) pixels at the target's depth.
void pan_pixels(Camera& camera, const ViewRect& rect, double dx, double dy);

// Zooms by `factor` (> 1: closer) keeping the point under `pixel` on the target plane fixed.
void zoom_at(Camera& camera, const ViewRect& rect, const Vec2& pixel, double factor);

}  // namespace pl
