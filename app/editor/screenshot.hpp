// Screenshot export: the view (or the comparison) rendered offscreen at a chosen resolution,
// not the window's, with the UI hidden, an optional transparent background, panel labels and
// the colour legend burned in (the renderer's offscreen target, text and legend code). Needs a
// current GL context.
#pragma once

#include <string>
#include <vector>

#include "render/image.hpp"
#include "render/legend.hpp"
#include "render/scene_renderer.hpp"

namespace pl {

struct ShotPanel {
  const GpuScene* scene = nullptr;
  DisplaySettings settings;
  ColorRange range;
  std::string label;
};

struct ShotRequest {
  int width = 1920, height = 1080;
  Camera camera;  // as in the window; the aspect is that of one panel of the shot
  std::vector<ShotPanel> panels;
  bool transparent = false;
  // The legends at the right edge, one under the other: those the window shows beside the view
  // (view_legends), so the picture reads as the window does.
  std::vector<LegendSpec> legends;
};

// Throws std::runtime_error when the driver refuses the size.
Image render_screenshot(const SceneRenderer& renderer, const ShotRequest& request);

}  // namespace pl
