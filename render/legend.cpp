#include "render/legend.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "render/text.hpp"

namespace pl {

std::string format_tick(double value) {
  if (value == 0) return "0";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", value);
  return buf;
}

int legend_scale(int width, int height) {
  // One font pixel per 400 image pixels of the smaller dimension (a 4:3 frame's height).
  const double side = std::min(width * 0.75, static_cast<double>(height));
  return std::max(1, static_cast<int>(std::ceil(side / 400.0)));
}

namespace {

struct LegendMetrics {
  int u, bar_w, tick_len, gap, pad, label_w, title_w, panel_w, margin;
};

LegendMetrics metrics(const ColorRange& range, const std::string& title, int scale) {
  LegendMetrics m{};
  m.u = scale;
  m.bar_w = 7 * scale;
  m.tick_len = 3 * scale;
  m.gap = 3 * scale;  // keeps a tick apart from a label's minus sign
  m.pad = 6 * scale;
  m.margin = 8 * scale;
  for (double t : {range.hi, 0.5 * range.hi, 0.0, 0.5 * range.lo, range.lo})
    m.label_w = std::max(m.label_w, text_width(format_tick(t), scale));
  m.title_w = text_width(title, scale);
  m.panel_w = std::max(m.bar_w + m.tick_len + m.gap + m.label_w, m.title_w) + 2 * m.pad;
  return m;
}

}  // namespace

int legend_reserved_width(const ColorRange& range, const std::string& title, int scale) {
  const LegendMetrics m = metrics(range, title, scale);
  return m.panel_w + 2 * m.margin;
}

void draw_legend(Image& image, const ColorRange& range, const std::string& title, int scale) {
  const LegendMetrics m = metrics(range, title, scale);
  const int u = scale;
  const int bar_w = m.bar_w, bar_h = std::max(40, image.height / 2);
  const double ticks[5] = {range.hi, 0.5 * range.hi, 0.0, 0.5 * range.lo, range.lo};
  const int pad = m.pad, tick_len = m.tick_len;
  const int panel_w = m.panel_w;
  const int panel_h = bar_h + text_height(u) + 6 * u + 2 * pad;
  const int x0 = image.width - panel_w - m.margin;
  const int y0 = (image.height - panel_h) / 2;
  fill_rounded_rect(image, x0, y0, x0 + panel_w, y0 + panel_h, 4 * u, {1.0f, 1.0f, 1.0f}, 0.82f);

  const std::array<float, 3> ink{0.13f, 0.14f, 0.17f};
  draw_text(image, x0 + pad, y0 + pad, title, u, ink);
  const int bx = x0 + pad, by = y0 + pad + text_height(u) + 6 * u;
  // Top of the bar is hi: row y maps linearly to t = 1 .. 0.
  for (int y = 0; y < bar_h; ++y) {
    const double t = 1.0 - (y + 0.5) / bar_h;
    const Rgb c = color_map(t);
    for (int x = 0; x < bar_w; ++x) image.blend(bx + x, by + y, c, 1.0f);
  }
  // A thin frame keeps the neutral middle visible on a white panel.
  for (int x = -1; x <= bar_w; ++x) {
    image.blend(bx + x, by - 1, ink, 0.6f);
    image.blend(bx + x, by + bar_h, ink, 0.6f);
  }
  for (int y = 0; y < bar_h; ++y) {
    image.blend(bx - 1, by + y, ink, 0.6f);
    image.blend(bx + bar_w, by + y, ink, 0.6f);
  }
  for (int i = 0; i < 5; ++i) {
    // Ticks at t = 1, 0.75, 0.5, 0.25, 0: the map is piecewise linear with 0 at the middle.
    const int y = by + static_cast<int>(std::lround(i * (bar_h - 1) / 4.0));
    for (int k = 0; k < tick_len; ++k)
      for (int w = 0; w < std::max(1, u / 2 + 1); ++w)
        image.blend(bx + bar_w + k, y + w, ink, 1.0f);
    draw_text(image, bx + bar_w + tick_len + m.gap, y - text_height(u) / 2 + 1,
              format_tick(ticks[i]), u, ink);
  }
}

}  // namespace pl
