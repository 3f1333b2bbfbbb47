#include "app/editor/logic/editor_layout.hpp"

#include <algorithm>
#include <cmath>

#include "app/editor/logic/compare_layout.hpp"

namespace pl {

double EditorLayout::legend_width() const {
  if (legends <= 0) return 0;
  const double free = std::max(0.0, display.x - side_panel_width());
  return std::floor(std::min(kLegendWidth * ui_scale, free / 3));
}

double EditorLayout::table_strip_height() const {
  if (table_height <= 0) return 0;
  const double free = std::max(0.0, display.y - menu_height - status_height);
  return std::floor(std::min(table_height, free / 3));
}

ViewRect EditorLayout::viewport() const {
  return {0, menu_height, std::max(1.0, display.x - side_panel_width() - legend_width()),
          std::max(1.0, display.y - menu_height - status_height - table_strip_height())};
}

ViewRect EditorLayout::table_strip() const {
  const ViewRect v = viewport();
  return {v.x, v.y + v.height, v.width + legend_width(), table_strip_height()};
}

ViewRect EditorLayout::legend_column() const {
  const ViewRect v = viewport();
  return {v.x + v.width, v.y, legend_width(), v.height};
}

std::vector<ViewRect> EditorLayout::panels(int count) const {
  return pane_rects(viewport(), count);
}

int EditorLayout::panel_at(const Vec2& pixel, int count) const {
  const auto rects = panels(count);
  for (std::size_t i = 0; i < rects.size(); ++i)
    if (rects[i].contains(pixel)) return static_cast<int>(i);
  return -1;
}

std::vector<LegendSpec> view_legends(const DisplaySettings& d, bool compare, bool difference,
                                     bool surfaces, const ColorRange& curvature,
                                     double distance_range, const std::string& base) {
  std::vector<LegendSpec> r;
  if (!surfaces) return r;  // a range of nothing: the placeholder's -1 ... 1 would mislead
  const bool distance = compare && difference;
  if (d.base == BaseMode::Curvature) {
    const std::string what = std::string(curvature_name(d.curvature)) + " curvature";
    r.push_back({distance ? base + ": " + what : what, curvature});
  }
  if (distance) r.push_back({"distance to " + base, {-distance_range, distance_range}});
  return r;
}

}  // namespace pl
