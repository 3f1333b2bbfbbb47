// Where the editor's parts sit in the window: the 3D view between the menu bar, the side panel
// (right) and the status bar, split in two panels side by side for the comparison, and, when a
// colour map is shown, a column for its legends between the view and the side panel, so a
// legend never covers either panel. What the legends and the comparison's titles say is
// decided here too. GUI-free and unit-tested; the window layer gives the sizes ImGui measured.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "app/editor/logic/view_math.hpp"
#include "render/display_settings.hpp"
#include "render/legend.hpp"

namespace pl {

struct EditorLayout {
  Vec2 display{1, 1};      // window size in pixels
  double menu_height = 0;  // menu bar
  double status_height = 0;
  double ui_scale = 1;
  int legends = 0;  // legends shown in the legend column (0: no column)
  static constexpr double kSidePanelWidth = 340.0;  // at UI scale 1
  static constexpr double kLegendWidth = 150.0;     // at UI scale 1

  double side_panel_width() const { return kSidePanelWidth * ui_scale; }
  double legend_width() const;  // 0 without legends; never more than a third of the free width
  ViewRect viewport() const;    // the area left for the 3D view
  ViewRect legend_column() const;
  // One panel, or two halves of the viewport (Gregory | GB).
  std::vector<ViewRect> panels(bool compare) const;
  // Index of the panel holding `pixel`, or -1.
  int panel_at(const Vec2& pixel, bool compare) const;
};

// The legends the view needs: the curvature map's (one range for both panels of the comparison,
// so one legend, said to be the Gregory view's when GB shows distances), and the distance
// colouring's (the GB panel of the comparison).
std::vector<LegendSpec> view_legends(const DisplaySettings& display, bool compare, bool difference,
                                     const ColorRange& curvature, double distance_range);

// The title of comparison panel `panel` that fits `width` pixels, as measured by `text_width`:
// the full one, else shorter ones ("GB: distance to Gregory", "GB").
std::string compare_panel_title(int panel, bool difference, double width,
                                const std::function<double(const std::string&)>& text_width);

}  // namespace pl
