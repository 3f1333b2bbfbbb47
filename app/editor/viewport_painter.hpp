// Draws the 3D view: each panel's filling with the renderer, then over it the work-plane grid,
// the selection (faces tinted, edges and face borders in the accent colour, depth-tested so
// hidden parts stay hidden; in the curvature colours outlined only, the colours untouched), the
// object under the cursor (a lighter tint, or its outline), and the ImGui overlays (selected and
// hovered points, tooltips, the curves' knot ticks and joints, faint where a surface hides them,
// panel labels, axis triad). Owns the GPU copies of those highlight lines, re-uploaded only when
// the selection, the hover or the document changes. Needs a current GL context and an ImGui
// frame.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "app/editor/gl_window.hpp"
#include "app/editor/logic/editor_model.hpp"
#include "render/reduced_target.hpp"
#include "render/scene_renderer.hpp"

namespace pl {

// Everything one frame of the view shows.
struct ViewportFrame {
  const GlWindow* window = nullptr;
  const SceneRenderer* renderer = nullptr;
  EditorModel* model = nullptr;  // what is drawn: the views, the selection, the hover, ...
  ViewRect viewport;             // the whole 3D area
  std::vector<ViewRect> panels;  // one per view panel
  float ui_scale = 1;
};

class ViewportPainter {
 public:
  // Draws the panels and their overlays; `range` is the common curvature colour range.
  void paint(const ViewportFrame& f, const ColorRange& range);

 private:
  // The highlight lines of one panel, uploaded when their key changes.
  struct PanelGuides {
    GpuPrimitives selected, hovered, grid, axis_u, axis_v;
    uint64_t selected_key = UINT64_MAX, hovered_key = UINT64_MAX;
    std::vector<int> selected_surfaces;
    int hovered_surface = -1;
    // Per point of curve_mark_points: 1 where no surface of the panel hides it.
    std::vector<char> marks_seen;
  };
  // colour_mode: the panel's colours carry values (colours_carry_values), so the surface under
  // the cursor is outlined instead of tinted.
  void update_guides(const ViewportFrame& f, int panel, bool colour_mode);
  // While the scene is evaluated behind it: a panel with a progress bar.
  void draw_progress(const ViewportFrame& f);
  void draw_panel_gl(const ViewportFrame& f, int panel, const ColorRange& range,
                     const DisplaySettings& display);
  std::array<PanelGuides, kMaxComparePanes> guides_;
  ReducedTarget reduced_;  // the view drawn smaller while moving (draw budget)
};

}  // namespace pl
