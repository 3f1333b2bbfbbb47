#include "render/frame.hpp"

#include <algorithm>
#include <stdexcept>

#include "render/legend.hpp"
#include "render/offscreen_target.hpp"
#include "render/palette.hpp"
#include "render/text.hpp"

namespace pl {

namespace {

// Line widths and point sizes are designed for this image height.
constexpr double kReferenceHeight = 1000.0;

std::optional<LegendSpec> legend_of(const FrameRequest& r) {
  if (r.legend) return r.legend;
  if (r.settings.base == BaseMode::Curvature)
    return LegendSpec{std::string(curvature_name(r.settings.curvature)) + " curvature", r.range};
  return std::nullopt;
}

PointKeyEntries key_entries(const FrameRequest& r) {
  if (r.key_entries) return *r.key_entries;
  PointKeyEntries e;
  for (const FramePanel& p : r.panels) {
    if (!p.settings.value_or(r.settings).control_net || !p.scene) continue;
    e.point_styles |= p.scene->point_styles();
    e.arrow_kinds |= p.scene->arrow_kinds();
  }
  return e;
}

}  // namespace

FrameLayout frame_layout(const FrameRequest& r) {
  FrameLayout f;
  f.scale = legend_scale(r.width, r.height);
  // Below 0.75 dots and lines of small renders would be too thin to read.
  f.pixel_scale = std::max(0.75, r.height / kReferenceHeight);
  const int margin = panel_margin(f.scale);
  f.legend = legend_of(r);
  int column = 0, legend_h = 0;
  if (f.legend) {
    f.legend_bar = legend_bar_height(r.height);
    legend_h = legend_height(f.scale, f.legend_bar);
    column = legend_width(*f.legend, f.scale);
  }
  const PointKeyEntries entries = key_entries(r);
  if (r.point_key && !entries.empty()) {
    // Symbols a little larger than in the scene when the text is much larger, to stay legible.
    const PointKeyLayout key =
        point_key_layout(entries, f.scale, std::max(f.pixel_scale, 0.6 * f.scale));
    // Only where it fits under the legend (or alone) in the column.
    const int needed = key.height + 2 * margin + (f.legend ? legend_h + margin : 0);
    if (needed <= r.height) {
      f.key = key;
      column = std::max(column, key.width);
    }
  }
  int usable = r.width;
  if (column > 0) {
    // Never squeeze the model below half the image for the column's sake.
    usable = std::max(r.width / 2, r.width - column - 2 * margin);
    const int right = r.width - margin;  // the column's right edge
    if (f.legend) {
      f.legend_x = right - legend_width(*f.legend, f.scale);
      // Centred, unless the key below would overlap it: then just above the key.
      f.legend_y = (r.height - legend_h) / 2;
      if (f.key)
        f.legend_y = std::min(f.legend_y, r.height - margin - f.key->height - margin - legend_h);
      f.legend_y = std::max(margin, f.legend_y);
    }
    if (f.key) {
      f.key_x = right - f.key->width;
      f.key_y = r.height - margin - f.key->height;
    }
  }
  const int n = std::max<int>(1, static_cast<int>(r.panels.size()));
  for (int i = 0; i < n; ++i) {
    const int x0 = usable * i / n, x1 = usable * (i + 1) / n;
    f.panels.push_back({x0, 0, x1 - x0, r.height, f.pixel_scale});
  }
  return f;
}

double panel_aspect(const FrameRequest& r) {
  const Viewport v = frame_layout(r).panels.front();
  return static_cast<double>(v.width) / v.height;
}

double panel_aspect(int width, int height, int count, const DisplaySettings& settings,
                    const ColorRange& range) {
  FrameRequest r;
  r.width = width;
  r.height = height;
  r.settings = settings;
  r.range = range;
  r.point_key = false;
  r.panels.resize(static_cast<std::size_t>(std::max(1, count)));
  return panel_aspect(r);
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
  const FrameLayout layout = frame_layout(r);
  std::vector<const GpuScene*> scenes;
  for (const FramePanel& p : r.panels) scenes.push_back(p.scene);
  const DisplaySettings settings = common_comb_length(r.settings, scenes);
  Image image(r.width, r.height);
  {
    OffscreenTarget target(tw, th);
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
          const FramePanel& p = r.panels[i];
          Viewport v = layout.panels[i];
          if (v.x + v.width <= tx || v.x >= tx + tw) continue;
          // Keep each panel inside its own columns.
          glEnable(GL_SCISSOR_TEST);
          glScissor(v.x - tx, 0, v.width, th);
          v.x -= tx;
          v.y -= ty;
          DisplaySettings s = p.settings ? common_comb_length(*p.settings, scenes) : settings;
          renderer.draw(*p.scene, p.camera.value_or(r.camera), s, p.range.value_or(r.range), v);
          glDisable(GL_SCISSOR_TEST);
        }
        // GL row ty is image row height - ty - th .. counted from the top.
        target.read_into(image, tx, r.height - ty - th);
      }
  }

  const double u = layout.scale;
  const int margin = panel_margin(u);
  for (int i = 0; i < static_cast<int>(r.panels.size()); ++i) {
    if (r.panels[i].label.empty()) continue;
    draw_text(image, layout.panels[i].x + margin, margin, r.panels[i].label, 1.25 * u,
              palette::kInk);
  }
  if (layout.legend)
    draw_legend_at(image, *layout.legend, u, layout.legend_x, layout.legend_y, layout.legend_bar);
  if (layout.key)
    blend_image(image, render_point_key(renderer, *layout.key), layout.key_x, layout.key_y);
  return image;
}

}  // namespace pl
