#include "render/frame.hpp"

#include <algorithm>
#include <stdexcept>

#include "render/legend.hpp"
#include "render/offscreen_target.hpp"
#include "render/text.hpp"

namespace pl {

namespace {

// Line widths and point sizes are designed for this image height.
constexpr double kReferenceHeight = 1000.0;

std::string legend_title(const DisplaySettings& s) {
  return std::string(curvature_name(s.curvature)) + " curvature";
}

}  // namespace

std::vector<Viewport> panel_viewports(int width, int height, int count,
                                      const DisplaySettings& settings, const ColorRange& range) {
  int usable = width;
  if (settings.base == BaseMode::Curvature) {
    const int reserve =
        legend_reserved_width(range, legend_title(settings), legend_scale(width, height));
    // Never squeeze the model below half the image for the legend's sake.
    usable = std::max(width / 2, width - reserve);
  }
  std::vector<Viewport> out;
  const int n = std::max(1, count);
  for (int i = 0; i < n; ++i) {
    const int x0 = usable * i / n, x1 = usable * (i + 1) / n;
    out.push_back({x0, 0, x1 - x0, height, 1.0});
  }
  return out;
}

double panel_aspect(int width, int height, int count, const DisplaySettings& settings,
                    const ColorRange& range) {
  const Viewport v = panel_viewports(width, height, count, settings, range).front();
  return static_cast<double>(v.width) / v.height;
}

DisplaySettings common_comb_length(const DisplaySettings& settings,
                                   const std::vector<const GpuScene*>& scenes) {
  DisplaySettings s = settings;
  if (!s.combs || s.comb_length || scenes.size() < 2) return s;
  // The smallest: the panel with the strongest reference curvature keeps its teeth in bounds.
  double length = 0;
  for (const GpuScene* g : scenes)
    if (g->comb_scale() > 0)
      length = length > 0 ? std::min(length, g->comb_scale()) : g->comb_scale();
  if (length > 0) s.comb_length = length;
  return s;
}

Image render_frame(const SceneRenderer& renderer, const FrameRequest& r) {
  if (r.width < 1 || r.height < 1 || r.panels.empty())
    throw std::invalid_argument("render_frame: empty image or no panels");
  const int tile = std::max(1, std::min(r.tile_size, OffscreenTarget::max_size()));
  const int tw = std::min(tile, r.width), th = std::min(tile, r.height);
  OffscreenTarget target(tw, th);
  Image image(r.width, r.height);
  // Below 0.75 dots and lines of small renders would be too thin to read.
  const double pixel_scale = std::max(0.75, r.height / kReferenceHeight);
  const std::vector<Viewport> panels =
      panel_viewports(r.width, r.height, static_cast<int>(r.panels.size()), r.settings, r.range);
  std::vector<const GpuScene*> scenes;
  for (const FramePanel& p : r.panels) scenes.push_back(p.scene);
  const DisplaySettings settings = common_comb_length(r.settings, scenes);

  // Tiles in GL's bottom-left pixel coordinates of the whole image; each panel keeps its full
  // viewport, shifted by the tile origin, so tiles join seamlessly and line widths stay in
  // whole-image pixels.
  for (int ty = 0; ty < r.height; ty += th)
    for (int tx = 0; tx < r.width; tx += tw) {
      target.bind();
      glClearColor(0, 0, 0, 0);
      glClearDepth(1.0);
      glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
      if (!r.settings.transparent) renderer.draw_backdrop({-tx, -ty, r.width, r.height, 1.0});
      for (int i = 0; i < static_cast<int>(r.panels.size()); ++i) {
        Viewport v = panels[i];
        if (v.x + v.width <= tx || v.x >= tx + tw) continue;
        // Keep each panel inside its own columns.
        glEnable(GL_SCISSOR_TEST);
        glScissor(v.x - tx, 0, v.width, th);
        v.x -= tx;
        v.y -= ty;
        v.pixel_scale = pixel_scale;
        renderer.draw(*r.panels[i].scene, r.camera, settings, r.range, v);
        glDisable(GL_SCISSOR_TEST);
      }
      // GL row ty is image row height - ty - th .. counted from the top.
      target.read_into(image, tx, r.height - ty - th);
    }

  const int scale = legend_scale(r.width, r.height);
  for (int i = 0; i < static_cast<int>(r.panels.size()); ++i) {
    if (r.panels[i].label.empty()) continue;
    const Viewport& v = panels[i];
    draw_text(image, v.x + 8 * scale, 8 * scale, r.panels[i].label, scale + 1,
              {0.13f, 0.14f, 0.17f});
  }
  if (r.settings.base == BaseMode::Curvature)
    draw_legend(image, r.range, std::string(curvature_name(r.settings.curvature)) + " curvature",
                scale);
  return image;
}

}  // namespace pl
