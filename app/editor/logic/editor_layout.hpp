// Where the editor's parts sit in the window: the 3D view between the menu bar, the side panel
// (right) and the status bar, split in two panels side by side for the comparison. GUI-free
// and unit-tested; the window layer gives the sizes ImGui measured.
#pragma once

#include <vector>

#include "app/editor/logic/view_math.hpp"

namespace pl {

struct EditorLayout {
  Vec2 display{1, 1};      // window size in pixels
  double menu_height = 0;  // menu bar
  double status_height = 0;
  double ui_scale = 1;
  static constexpr double kSidePanelWidth = 340.0;  // at UI scale 1

  double side_panel_width() const { return kSidePanelWidth * ui_scale; }
  ViewRect viewport() const;  // the area left for the 3D view
  // One panel, or two halves of the viewport (Gregory | GB).
  std::vector<ViewRect> panels(bool compare) const;
  // Index of the panel holding `pixel`, or -1.
  int panel_at(const Vec2& pixel, bool compare) const;
};

}  // namespace pl
