// The side panel: tools, selection inspector, display, work plane, comparison and continuity
// sections, one function each, over the parts they show. Every change of the document goes
// through a command or an action; the sections only lay out widgets. ImGui code.
#pragma once

#include <functional>
#include <string>

#include "app/editor/logic/actions.hpp"
#include "app/editor/logic/continuity_monitor.hpp"
#include "app/editor/logic/curve_marks.hpp"
#include "app/editor/logic/document_session.hpp"
#include "app/editor/logic/preferences.hpp"
#include "app/editor/logic/scene_views.hpp"
#include "app/editor/logic/selection.hpp"
#include "app/editor/logic/tool.hpp"

namespace pl {

struct SidePanel {
  Preferences& prefs;
  SceneViews& views;
  Document& doc;
  Selection& selection;
  const ActionRegistry& actions;
  const ContinuityMonitor& continuity;
  WorkPlane& work_plane;
  ToolBox& tools;
  ColorRange range;  // the colour range shown (a "fixed range" starts from it)
  float ui_scale = 1;
  ToolContext* tool_context = nullptr;      // what the active tool's options act through
  const CurveMarks* curve_marks = nullptr;  // the joints of the free curves (Continuity)
  // Scripts (--debug-state): told where a panel button is (its label and window rectangle).
  std::function<void(const std::string&, float, float, float, float)> item_probe;
};

// Draws the panel at the right of the window, between the bars. Returns true when the
// evaluation densities changed (the views must be rebuilt).
bool draw_side_panel(const SidePanel& p, double top, double bottom);

void draw_tools_section(const SidePanel& p);
// The active tool's own fields below its hint (typed coordinates of a new vertex).
void draw_tool_options(const SidePanel& p);
void draw_selection_section(const SidePanel& p);
// The free curve `curve` of the selected curve point `point` (in the Selection section).
void draw_curve_section(const SidePanel& p, int curve, int point);  // point -1: the whole curve
// Returns true when the densities changed.
bool draw_display_section(const SidePanel& p);
void draw_work_plane_section(const SidePanel& p);
// The comparison's panes, their schemes and base (in the Display section). Returns true when the
// panes changed (the views must be rebuilt).
bool draw_comparison_section(const SidePanel& p);
void draw_continuity_section(const SidePanel& p);
// Brings the Continuity figures up to the document once the views shown have settled: the
// scene's own filling, or the comparison's two (continuity_panel.cpp).

}  // namespace pl
