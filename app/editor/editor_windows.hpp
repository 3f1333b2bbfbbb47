// The editor's small windows: the status bar, the F1 help (the action table, the mouse gestures
// and the key of the control points' symbols), the probe read-out beside the cursor, the column
// of colour legends, and the busy indicator of long work. All opaque: nothing of the scene shows
// through them. ImGui code.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "app/editor/logic/actions.hpp"
#include "app/editor/logic/editor_layout.hpp"
#include "app/editor/logic/status_line.hpp"
#include "app/editor/logic/surface_probe.hpp"
#include "render/gl_objects.hpp"
#include "render/scene_renderer.hpp"

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

// The renderer's key of the control points' symbols (render_point_key) as a texture for F1,
// rendered once per scale: the symbols are exactly those the view draws.
class PointKeyImage {
 public:
  // Renders the key at this UI scale if it is not yet (needs the current GL context).
  void update(const SceneRenderer& renderer, double ui_scale, double pixel_scale);
  unsigned texture() const { return texture_ ? texture_->id() : 0; }
  int width() const { return width_; }
  int height() const { return height_; }
  double pixel_scale() const { return pixel_scale_; }

 private:
  std::optional<gl::Texture> texture_;
  int width_ = 0, height_ = 0;
  double scale_ = 0, pixel_scale_ = 1;
};

void draw_status_bar(const StatusLine& status, const StatusFigures& figures, float ui_scale);
// The mouse rows of F1 (editor_input.cpp, next to the code that handles them).
std::vector<HelpRow> mouse_help();
// Sized to fit the window whatever its size (the text wraps, the lists scroll). Returns true
// when it has the keyboard focus (Esc then closes it).
bool draw_help_window(bool* open, const ActionRegistry& actions, PointKeyImage& key,
                      const SceneRenderer& renderer, float ui_scale);
// `distance`: the comparison's GB-to-Gregory distance under the cursor, in difference mode.
void draw_probe_window(const ProbeHit& probe, const std::string& surface_name,
                       std::optional<double> distance, float ui_scale);
// The legends in their column (EditorLayout::legend_column), one under the other.
void draw_legend_column(const ViewRect& column, std::span<const LegendSpec> legends,
                        float ui_scale);
// "Exporting part.step  3 s" with a spinner, at the bottom right of the view.
void draw_busy_window(const std::string& what, double seconds, float ui_scale);

}  // namespace pl
