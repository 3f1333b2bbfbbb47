// Which world points the surfaces already drawn hide: the depth buffer of the framebuffer bound
// for drawing, read back around the points. For marks drawn in 2D over a view (the editor's knot
// ticks and joint labels, ImGui): they have no depth of their own, so without this they show
// through the surfaces in front of the curves they mark. Needs a current GL context.
#pragma once

#include <span>
#include <vector>

#include "core/math/vec.hpp"
#include "render/camera.hpp"
#include "render/scene_renderer.hpp"

namespace pl {

// Per point: 1 when it is in front of (or on) what the bound framebuffer's depth holds within
// `viewport`, 0 when a surface drawn there is nearer the eye, as the renderer's overlay lines
// decide it (kOverlayDepthBias, so a point on a surface counts as seen). A point is compared
// with the farthest depth among its pixel and the 8 around it: a mark at a silhouette shows.
// Points behind the eye or cut by the near or far plane are 0; points outside the viewport 1
// (nothing there to hide them). Reads a multisampled framebuffer through a resolved copy of its
// depth.
std::vector<char> points_seen(const Camera& camera, const Viewport& viewport,
                              std::span<const Vec3> points);

}  // namespace pl
