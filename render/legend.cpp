#include "render/legend.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "render/palette.hpp"
#include "render/text.hpp"

namespace pl {

std::string format_tick(double value) {
  if (value == 0) return "0";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", value);
  return buf;
}

double legend_scale(int width, int height) {
  // One unit per 400 image pixels of the smaller dimension (a 4:3 frame's height).
  const double side = std::min(width * 0.75, static_cast<double>(height));
  return std::max(1.0, side / 400.0);
}

namespace {

struct Metrics {
  int bar_w, tick_len, gap, pad, label_w, title_w, title_gap, width;
};

Metrics metrics(const LegendSpec& legend, double u) {
  Metrics m{};
  auto px = [&](double units) { return static_cast<int>(std::lround(units * u)); };
  m.bar_w = px(8);
  m.tick_len = px(3);
  m.gap = px(3);  // keeps a tick apart from a label's minus sign
  m.pad = px(7);
  m.title_gap = px(7);
  const ColorRange& r = legend.range;
  for (double t : {r.hi, 0.5 * r.hi, 0.0, 0.5 * r.lo, r.lo})
    m.label_w = std::max(m.label_w, text_width(format_tick(t), u));
  m.title_w = text_width(legend.title, u);
  m.width = std::max(m.bar_w + m.tick_len + m.gap + m.label_w, m.title_w) + 2 * m.pad;
  return m;
}

}  // namespace

int legend_width(const LegendSpec& legend, double scale) {
  return metrics(legend, scale).width;
}

int legend_height(double scale, int bar_height) {
  const int pad = static_cast<int>(std::lround(7 * scale));
  // Title capitals, the gap under them, the bar with half a tick label above and below it.
  return 2 * pad + 2 * text_height(scale) + static_cast<int>(std::lround(7 * scale)) + bar_height;
}

int legend_bar_height(int image_height) {
  return std::max(40, image_height / 2);
}

void draw_legend_at(Image& image, const LegendSpec& legend, double u, int x0, int y0, int bar_h) {
  const Metrics m = metrics(legend, u);
  const int h = legend_height(u, bar_h);
  const int radius = static_cast<int>(std::lround(4 * u));
  // Opaque: nothing of the model or its overlays shows through the numbers.
  fill_rounded_rect(image, x0, y0, x0 + m.width, y0 + h, radius, palette::kPanel, 1.0f);
  stroke_rounded_rect(image, x0, y0, x0 + m.width, y0 + h, radius, std::max(1.0, 0.5 * u),
                      palette::kPanelFrame, 1.0f);
  const Rgb& ink = palette::kInk;
  draw_text(image, x0 + m.pad, y0 + m.pad, legend.title, u, ink);
  const int bx = x0 + m.pad, by = y0 + m.pad + text_height(u) + m.title_gap + text_height(u) / 2;
  // Top of the bar is hi: row y maps linearly to t = 1 .. 0.
  for (int y = 0; y < bar_h; ++y) {
    const Rgb c = color_map(1.0 - (y + 0.5) / bar_h);
    for (int x = 0; x < m.bar_w; ++x) image.blend(bx + x, by + y, c, 1.0f);
  }
  // A thin frame keeps the neutral middle visible on a white panel.
  const int line = std::max(1, static_cast<int>(std::lround(0.4 * u)));
  for (int w = 1; w <= line; ++w) {
    for (int x = -w; x < m.bar_w + w; ++x) {
      image.blend(bx + x, by - w, ink, 0.6f);
      image.blend(bx + x, by + bar_h - 1 + w, ink, 0.6f);
    }
    for (int y = 0; y < bar_h; ++y) {
      image.blend(bx - w, by + y, ink, 0.6f);
      image.blend(bx + m.bar_w - 1 + w, by + y, ink, 0.6f);
    }
  }
  const ColorRange& r = legend.range;
  const double ticks[5] = {r.hi, 0.5 * r.hi, 0.0, 0.5 * r.lo, r.lo};
  const int tick_w = std::max(1, static_cast<int>(std::lround(0.6 * u)));
  for (int i = 0; i < 5; ++i) {
    // Ticks at t = 1, 0.75, 0.5, 0.25, 0: the map is piecewise linear with 0 at the middle.
    const int y = by + static_cast<int>(std::lround(i * (bar_h - 1) / 4.0));
    for (int k = 0; k < m.tick_len; ++k)
      for (int w = 0; w < tick_w; ++w) image.blend(bx + m.bar_w + k, y - tick_w / 2 + w, ink, 1.0f);
    draw_text(image, bx + m.bar_w + m.tick_len + m.gap, y - text_height(u) / 2,
              format_tick(ticks[i]), u, ink);
  }
}

int legend_reserved_width(const ColorRange& range, const std::string& title, double scale) {
  return legend_width({title, range}, scale) + 2 * panel_margin(scale);
}

void draw_legend(Image& image, const ColorRange& range, const std::string& title, double scale) {
  const LegendSpec legend{title, range};
  const int bar_h = legend_bar_height(image.height);
  const int x = image.width - legend_width(legend, scale) - panel_margin(scale);
  const int y = (image.height - legend_height(scale, bar_h)) / 2;
  draw_legend_at(image, legend, scale, x, y, bar_h);
}

void draw_legends(Image& image, const std::vector<LegendSpec>& legends, double scale) {
  if (legends.empty()) return;
  const int n = static_cast<int>(legends.size()), margin = panel_margin(scale);
  // The height of one legend alone, shared out: each panel's frame and the gaps between them
  // come out of it (one legend is exactly draw_legend's).
  const int frame = legend_height(scale, 0);
  const int alone = frame + legend_bar_height(image.height);
  const int bar = std::max(40, (alone - (n - 1) * margin) / n - frame);
  const int total = n * legend_height(scale, bar) + (n - 1) * margin;
  int y = (image.height - total) / 2;
  for (const LegendSpec& legend : legends) {
    const int x = image.width - legend_width(legend, scale) - margin;
    draw_legend_at(image, legend, scale, x, y, bar);
    y += legend_height(scale, bar) + margin;
  }
}

}  // namespace pl
