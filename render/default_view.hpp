// The view a scene opens with when none is asked for: the iso view, unless that sees the surfaces
// from behind or nearly edge-on, more than 75 degrees from their mean normal (a single patch such
// as a .gbp often faces away from the iso direction). Then the camera looks at their front, along
// the area-weighted mean normal tilted towards the iso direction so the shape still reads in
// depth. Either way the view is framed tightly on everything drawn. GL-free: the editor opens a
// scene with the same camera.
#pragma once

#include <optional>
#include <span>

#include "render/camera.hpp"
#include "render/display_settings.hpp"
#include "render/draw_scene.hpp"

namespace pl {

// The area-weighted mean of the surfaces' unit normals (by triangle). Its length, 0 to 1, says how
// one-sided they are: 1 for a plane, near 0 for a closed shape. Zero without surfaces.
Vec3 mean_normal(std::span<const SurfaceMesh* const> meshes);

// The front's direction when the iso view would not see it well: the unit mean normal, or
// nullopt when the iso view is kept.
std::optional<Vec3> facing_direction(std::span<const SurfaceMesh* const> meshes);

// The default camera for the scenes drawn side by side (one camera for all), framed on their
// surfaces, nets, arrows and curves at this aspect, and with `settings` showing combs, on the
// combs' tips too. Facing a front, the camera looks along the normal tilted 15 degrees, towards
// whichever side makes the front fill most of the view.
Camera default_camera(std::span<const DrawScene* const> scenes, double aspect,
                      const DisplaySettings* settings = nullptr);
// The same for meshes alone, framed on `points` (empty: on the meshes' vertices).
Camera default_camera_of(std::span<const SurfaceMesh* const> meshes, std::span<const Vec3> points,
                         double aspect);
// Its eye direction (unit, from the target towards the eye) at a 4:3 aspect.
Vec3 default_view_direction(std::span<const SurfaceMesh* const> meshes);

// Every point a frame should contain: surface vertices, control points, arrow ends, curve points
// (network and free curves), and with `settings` showing combs the comb tips.
std::vector<Vec3> framing_points(std::span<const DrawScene* const> scenes,
                                 const DisplaySettings* settings = nullptr);

// The tips of every comb of `scene` where the renderer draws them with `settings`: tooth length
// per unit curvature comb_length (else the scene's automatic scale) times comb_scale, each tooth
// cut to kCombCap reference lengths.
// The tips of the teeth of `combs` drawn `scale` long per unit curvature, each tooth at most `cap`
// long (cap <= 0: no cap), appended to `out` (non-finite teeth left out): the renderer's sizing,
// shared with the editor's framing of several panes.
void append_tooth_tips(std::span<const CurvatureComb* const> combs, double scale, double cap,
                       std::vector<Vec3>& out);
void append_comb_tips(const DrawScene& scene, const DisplaySettings& settings,
                      std::vector<Vec3>& out);

}  // namespace pl
