// Where the editor's parts sit in the window: the 3D view between the menu bar, the side panel
// (right) and the status bar, split into the comparison's panes (compare_layout.hpp) with its
// table of figures under them, and, when a colour map is shown, a column for its legends between
// the view and the side panel, so a legend never covers a pane. What the legends say is decided
// here too. GUI-free and unit-tested; the window layer gives the sizes ImGui measured.
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
  // The comparison's table of figures under the panes (0: none); it never takes more than a
  // third of the height between the bars.
  double table_height = 0;
  static constexpr double kSidePanelWidth = 340.0;  // at UI scale 1
  static constexpr double kLegendWidth = 150.0;     // at UI scale 1

  double side_panel_width() const { return kSidePanelWidth * ui_scale; }
  double legend_width() const;  // 0 without legends; never more than a third of the free width
  ViewRect viewport() const;    // the area left for the 3D view
  ViewRect legend_column() const;
  double table_strip_height() const;
  ViewRect table_strip() const;  // under the view and the legends
  // The viewport whole (count 1), or split into the comparison's panes (pane_rects).
  std::vector<ViewRect> panels(int count) const;
  std::vector<ViewRect> panels(bool) const = delete;  // a count, not a switch
  // Index of the panel holding `pixel`, or -1.
  int panel_at(const Vec2& pixel, int count) const;
  int panel_at(const Vec2& pixel, bool) const = delete;
};

// The legends the view needs: the curvature map's (one range for every pane of the comparison,
// so one legend, said to be the base pane's when the others show distances), and the distance
// colouring's (every pane but the base's), `base` naming the base scheme. Both colour surfaces:
// with no surface shown (`surfaces` false: an empty scene, curves only) there is none.
std::vector<LegendSpec> view_legends(const DisplaySettings& display, bool compare, bool difference,
                                     bool surfaces, const ColorRange& curvature,
                                     double distance_range, const std::string& base = "Gregory");

}  // namespace pl
