// Turns an evaluated scene into the renderer's plain arrays (render/draw_scene.hpp): meshes with
// exact normals and curvatures, the control net with point kinds, network curves and patch
// borders with their curvature combs (comb_teeth tooth intervals per curve). The app does this so
// the renderer never sees patch classes.
#pragma once

#include "core/eval/scene_surfaces.hpp"
#include "core/scene/scene.hpp"
#include "render/display_settings.hpp"
#include "render/draw_scene.hpp"

namespace pl {

DrawScene build_draw_scene(const Scene& scene, const SceneSurfaces& surfaces,
                           int comb_teeth = DisplaySettings().comb_teeth);

}  // namespace pl
