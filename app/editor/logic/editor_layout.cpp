#include "app/editor/logic/editor_layout.hpp"

#include <algorithm>
#include <cmath>

namespace pl {

double EditorLayout::legend_width() const {
  if (legends <= 0) return 0;
  const double free = std::max(0.0, display.x - side_panel_width());
  return std::floor(std::min(kLegendWidth * ui_scale, free / 3));
}

ViewRect EditorLayout::viewport() const {
  return {0, menu_height, std::max(1.0, display.x - side_panel_width() - legend_width()),
          std::max(1.0, display.y - menu_height - status_height)};
}

ViewRect EditorLayout::legend_column() const {
  const ViewRect v = viewport();
  return {v.x + v.width, v.y, legend_width(), v.height};
}

std::vector<ViewRect> EditorLayout::panels(bool compare) const {
  const ViewRect r = viewport();
  if (!compare) return {r};
  const double half = std::floor(r.width / 2);
  return {{r.x, r.y, half, r.height}, {r.x + half, r.y, r.width - half, r.height}};
}

int EditorLayout::panel_at(const Vec2& pixel, bool compare) const {
  const auto rects = panels(compare);
  for (std::size_t i = 0; i < rects.size(); ++i)
    if (rects[i].contains(pixel)) return static_cast<int>(i);
  return -1;
}

std::vector<LegendSpec> view_legends(const DisplaySettings& d, bool compare, bool difference,
                                     const ColorRange& curvature, double distance_range) {
  std::vector<LegendSpec> r;
  const bool distance = compare && difference;
  if (d.base == BaseMode::Curvature) {
    const std::string what = std::string(curvature_name(d.curvature)) + " curvature";
    r.push_back({distance ? "Gregory: " + what : what, curvature});
  }
  if (distance) r.push_back({"GB: distance to Gregory", {-distance_range, distance_range}});
  return r;
}

std::string compare_panel_title(int panel, bool difference, double width,
                                const std::function<double(const std::string&)>& text_width) {
  const std::vector<std::string> titles =
      panel == 0   ? std::vector<std::string>{"Gregory"}
      : difference ? std::vector<std::string>{"Generalized Bezier, coloured by distance to Gregory",
                                              "GB: distance to Gregory", "GB"}
                   : std::vector<std::string>{"Generalized Bezier", "GB"};
  for (const std::string& t : titles)
    if (text_width(t) <= width) return t;
  return titles.back();
}

}  // namespace pl
