#include "app/editor/logic/editor_layout.hpp"

#include <algorithm>
#include <cmath>

namespace pl {

ViewRect EditorLayout::viewport() const {
  return {0, menu_height, std::max(1.0, display.x - side_panel_width()),
          std::max(1.0, display.y - menu_height - status_height)};
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

}  // namespace pl
