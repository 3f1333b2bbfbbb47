// Where the curvature combs the views draw end: what Frame All must keep in view besides the
// drawn points, since a comb's teeth stand off its curve. The editor's drawn scenes do not hold
// the combs (each view's LiveCurves does, and hands them to its GPU copy), so the tips are
// computed here from those combs with the renderer's sizing (GpuScene::set_combs,
// SceneRenderer::draw_combs, common_comb_length in render/frame.cpp).
#pragma once

#include <span>
#include <vector>

#include "core/curve/curvature_comb.hpp"
#include "render/display_settings.hpp"

namespace pl {

struct ViewCombs {
  std::vector<const CurvatureComb*> combs;  // every comb the view holds
  double diagonal = 0;                      // of the box of what it draws (DrawScene::bounds)
};

// The tip of every sample's tooth of every comb with `settings` showing combs (none otherwise):
// tooth length per unit curvature settings.comb_length, else the views' automatic one (each
// view's automatic_comb_scale_of over its diagonal; with several views the smallest of them,
// which all share), times comb_scale, and cut at kCombCap reference lengths
// (kDefaultCombFraction of the view's diagonal, times comb_scale).
std::vector<Vec3> comb_tips(std::span<const ViewCombs> views, const DisplaySettings& settings);

}  // namespace pl
