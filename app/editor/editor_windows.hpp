// The editor's small windows: the status bar, the F1 help (drawn from the action table and the
// mouse gestures), and the probe read-out beside the cursor. ImGui code.
#pragma once

#include <string>
#include <vector>

#include "app/editor/logic/actions.hpp"
#include "app/editor/logic/status_line.hpp"
#include "app/editor/logic/surface_probe.hpp"

namespace pl {

struct StatusFigures {
  bool coarse = false;       // the drag evaluation is shown
  std::size_t selected = 0;  // items selected
  std::string under;         // what lies under the cursor ("face 1"), may be empty
  std::string plane;         // the cursor on the work plane, when its grid is shown
  std::string tool;          // the active tool's name
  // How the view is drawn when it is drawn with less than it could (face densities for their
  // size on screen, control points thinned), may be empty.
  std::string drawing;
};

void draw_status_bar(const StatusLine& status, const StatusFigures& figures, float ui_scale);
// The mouse rows of F1 (editor_input.cpp, next to the code that handles them).
std::vector<HelpRow> mouse_help();
void draw_help_window(bool* open, const ActionRegistry& actions, float ui_scale);
void draw_probe_window(const ProbeHit& probe, const std::string& surface_name, float ui_scale);

}  // namespace pl
