// The side panel: tools, selection inspector, display, work plane, comparison and continuity
// sections, one function each, over the editor model's parts. Every change of the document goes
// through a command or an action; the sections only lay out widgets. ImGui code.
#pragma once

#include <functional>
#include <string>

#include "app/editor/logic/editor_model.hpp"

namespace pl {

// What the panel shows and edits: the editor model's parts, and what the window adds.
struct SidePanel {
  EditorModel& model;
  ColorRange range;  // the colour range shown (a "fixed range" starts from it)
  float ui_scale = 1;
  ToolContext* tool_context = nullptr;  // what the active tool's options act through
  // Scripts (--debug-state): told where a panel button is (its label and window rectangle).
  std::function<void(const std::string&, float, float, float, float)> item_probe;
};

// Draws the panel at the right of the window, between the bars. Returns true when the
// evaluation densities changed (the views must be rebuilt).
bool draw_side_panel(const SidePanel& p, double top, double bottom);

void draw_tools_section(const SidePanel& p);
// The tooltip of the panel item just drawn, while it is hovered: beside the panel, over the view,
// level with the item, so it never covers the panel's own text (a tool's hint under the buttons,
// the notes under a field) as one under the cursor would. Told to scripts as "tooltip".
void panel_tooltip(const SidePanel& p, const std::string& text);
// The active tool's own fields below its hint (typed coordinates of a new vertex).
void draw_tool_options(const SidePanel& p);
void draw_selection_section(const SidePanel& p);
// Rotate, scale and move the selected points by typed values about a pivot (one undo step each).
void draw_transform_section(const SidePanel& p);
// The free curve `curve` of the selected curve point `point` (in the Selection section).
void draw_curve_section(const SidePanel& p, int curve, int point);  // point -1: the whole curve
// Returns true when the densities changed.
bool draw_display_section(const SidePanel& p);
void draw_work_plane_section(const SidePanel& p);
// The comparison's panes, their schemes and base (in the Display section). Returns true when the
// panes changed (the views must be rebuilt).
bool draw_comparison_section(const SidePanel& p);
void draw_continuity_section(const SidePanel& p);

}  // namespace pl
