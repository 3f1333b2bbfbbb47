// One finished picture: panels side by side (one, or two for a comparison), each a scene seen by
// the request's camera with its settings and colour range (a panel may override them, e.g. the
// comparison's distance colouring), rendered in tiles no larger than the driver allows; then
// labels, the colour legend and the key of the control net's symbols burned in, in a column at
// the right so that they never cover the model. Needs a current context.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "render/image.hpp"
#include "render/legend.hpp"
#include "render/point_key.hpp"
#include "render/scene_renderer.hpp"

namespace pl {

struct FramePanel {
  FramePanel() = default;
  FramePanel(const GpuScene* s, std::string l = {}) : scene(s), label(std::move(l)) {}

  const GpuScene* scene = nullptr;
  std::string label;  // drawn top-left of the panel when non-empty
  // This panel's own settings, range and camera; nullopt: the request's.
  std::optional<DisplaySettings> settings;
  std::optional<ColorRange> range;
  std::optional<Camera> camera;
};

struct FrameRequest {
  int width = 1600, height = 1200;
  std::vector<FramePanel> panels;
  Camera camera;  // framed for panel_aspect()
  DisplaySettings settings;
  ColorRange range;
  // The colour legend; nullopt: the curvature map's ("mean curvature" over `range`) when the base
  // mode is a curvature map, else none.
  std::optional<LegendSpec> legend;
  // The key of the control net's symbols (the entries the panels' scenes use), when the control
  // net is shown and the key fits in the column.
  bool point_key = true;
  // Its entries; nullopt: those of the panels' scenes (GpuScene::point_styles, arrow_kinds). Set
  // them (PointKeyEntries::of the DrawScenes) to lay the frame out before the scenes are uploaded.
  std::optional<PointKeyEntries> key_entries;
  int tile_size = 2048;  // further limited by the driver's maximum
};

// Where everything goes: the panels side by side, and the column at the right that holds the
// legend (vertically centred) and the point key (at the bottom) when there are any.
struct FrameLayout {
  std::vector<Viewport> panels;
  double scale = 1;        // UI scale of text and panels (legend_scale)
  double pixel_scale = 1;  // of lines and points
  std::optional<LegendSpec> legend;
  int legend_x = 0, legend_y = 0, legend_bar = 0;
  std::optional<PointKeyLayout> key;
  int key_x = 0, key_y = 0;
};
FrameLayout frame_layout(const FrameRequest& request);
// The aspect (width / height) of the first panel: frame the camera for it.
double panel_aspect(const FrameRequest& request);
// The same for `count` panels with these settings and range and no point key.
double panel_aspect(int width, int height, int count, const DisplaySettings& settings,
                    const ColorRange& range);

// `settings` with comb_length fixed for every panel (the smallest automatic one among them), so
// that equal teeth side by side mean equal curvature, as one colour range does for the maps.
// Unchanged without combs, with comb_length already set, or for one panel.
DisplaySettings common_comb_length(const DisplaySettings& settings,
                                   const std::vector<const GpuScene*>& scenes);

Image render_frame(const SceneRenderer& renderer, const FrameRequest& request);

}  // namespace pl
