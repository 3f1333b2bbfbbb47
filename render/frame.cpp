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

Viewport panel_viewport(const FrameRequest& r, int i) {
  const int n = static_cast<int>(r.panels.size());
  const int x0 = r.width * i / n, x1 = r.width * (i + 1) / n;
  return {x0, 0, x1 - x0, r.height, 1.0};
}

}  // namespace

double panel_aspect(int width, int height, int count) {
  return (static_cast<double>(width) / std::max(1, count)) / std::max(1, height);
}

Image render_frame(const SceneRenderer& renderer, const FrameRequest& r) {
  if (r.width < 1 || r.height < 1 || r.panels.empty())
    throw std::invalid_argument("render_frame: empty image or no panels");
  const int tile = std::max(1, std::min(r.tile_size, OffscreenTarget::max_size()));
  const int tw = std::min(tile, r.width), th = std::min(tile, r.height);
  OffscreenTarget target(tw, th);
  Image image(r.width, r.height);
  const double pixel_scale = std::max(0.5, r.height / kReferenceHeight);

  // Tiles in GL's bottom-left pixel coordinates of the whole image; each panel keeps its full
  // viewport, shifted by the tile origin, so tiles join seamlessly and line widths stay in
  // whole-image pixels.
  for (int ty = 0; ty < r.height; ty += th)
    for (int tx = 0; tx < r.width; tx += tw) {
      target.bind();
      glClearColor(0, 0, 0, 0);
      glClearDepth(1.0);
      glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
      for (int i = 0; i < static_cast<int>(r.panels.size()); ++i) {
        Viewport v = panel_viewport(r, i);
        if (v.x + v.width <= tx || v.x >= tx + tw) continue;
        // Keep each panel inside its own columns: the backdrop covers its whole viewport.
        glEnable(GL_SCISSOR_TEST);
        glScissor(v.x - tx, 0, v.width, th);
        v.x -= tx;
        v.y -= ty;
        v.pixel_scale = pixel_scale;
        renderer.draw(*r.panels[i].scene, r.camera, r.settings, r.range, v);
        glDisable(GL_SCISSOR_TEST);
      }
      // GL row ty is image row height - ty - th .. counted from the top.
      target.read_into(image, tx, r.height - ty - th);
    }

  const int scale = legend_scale(r.width, r.height);
  for (int i = 0; i < static_cast<int>(r.panels.size()); ++i) {
    if (r.panels[i].label.empty()) continue;
    const Viewport v = panel_viewport(r, i);
    draw_text(image, v.x + 8 * scale, 8 * scale, r.panels[i].label, scale + 1,
              {0.13f, 0.14f, 0.17f});
  }
  if (r.settings.base == BaseMode::Curvature)
    draw_legend(image, r.range, std::string(curvature_name(r.settings.curvature)) + " curvature",
                scale);
  return image;
}

}  // namespace pl
