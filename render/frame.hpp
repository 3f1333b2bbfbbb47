// One finished picture: panels side by side (one, or two for --compare), each a scene seen by
// the same camera with the same settings and colour range, rendered in tiles no larger than the
// driver allows, then labels and the curvature legend burned in. Needs a current context.
#pragma once

#include <string>
#include <vector>

#include "render/image.hpp"
#include "render/scene_renderer.hpp"

namespace pl {

struct FramePanel {
  const GpuScene* scene = nullptr;
  std::string label;  // drawn top-left of the panel when non-empty
};

struct FrameRequest {
  int width = 1600, height = 1200;
  std::vector<FramePanel> panels;
  Camera camera;  // framed for panel_aspect()
  DisplaySettings settings;
  ColorRange range;
  int tile_size = 2048;  // further limited by the driver's maximum
};

// Where the panels go: side by side, leaving room at the right for the legend of a curvature
// mode. Frame the camera for the aspect of these viewports.
std::vector<Viewport> panel_viewports(int width, int height, int count,
                                      const DisplaySettings& settings, const ColorRange& range);
double panel_aspect(int width, int height, int count, const DisplaySettings& settings,
                    const ColorRange& range);

// `settings` with comb_length fixed for every panel (the smallest automatic one among them), so
// that equal teeth side by side mean equal curvature, as one colour range does for the maps.
// Unchanged without combs, with comb_length already set, or for one panel.
DisplaySettings common_comb_length(const DisplaySettings& settings,
                                   const std::vector<const GpuScene*>& scenes);

Image render_frame(const SceneRenderer& renderer, const FrameRequest& request);

}  // namespace pl
