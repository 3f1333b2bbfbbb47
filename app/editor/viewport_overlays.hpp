// The 2D overlays over a view panel, drawn with ImGui's background list (crisp at any scale, no
// GL programs): selected and hovered points with their tooltips, the worst continuity edge, the
// probe's mark, the comparison's panel labels, the axis triad, the tools' feedback and the
// tangent-plane discs of selected vertices (the colour legends have a column of their own:
// editor_windows).
#pragma once

#include <optional>
#include <string>

#include "app/editor/logic/continuity_monitor.hpp"
#include "app/editor/logic/curve_marks.hpp"
#include "app/editor/logic/live_surfaces.hpp"
#include "app/editor/logic/plane_handles.hpp"
#include "app/editor/logic/preferences.hpp"
#include "app/editor/logic/scene_picker.hpp"
#include "app/editor/logic/surface_probe.hpp"
#include "app/editor/logic/tool.hpp"

namespace pl {

struct OverlayFrame {
  const ViewRect& rect;
  const Camera& camera;
  const LiveSurfaces& live;  // what the panel shows
  const Preferences& prefs;
  const Selection& selection;
  const ContinuityMonitor* continuity;
  const PickResult* hover;  // null unless the cursor is over this panel
  const std::optional<ProbeHit>* probe;
  float ui_scale;
  int panel = 0;  // which view panel (the continuity figures of its filling)
  const CurveMarks* curve_marks = nullptr;
  // Per point of curve_mark_points(*curve_marks): 1 where no surface hides it (points_seen);
  // null or short: every mark counts as seen.
  const std::vector<char>* marks_seen = nullptr;
};

void draw_point_overlays(const OverlayFrame& o);
// The knots of the free curves as ticks across them (a multiple knot longer, with its
// multiplicity), their ends, and a label at each joint of two curves with its G0/G1/G2 figures
// (curve_overlays.cpp).
void draw_curve_marks(const OverlayFrame& o);
// The points the curve marks stand on, in the order draw_curve_marks reads their visibility:
// every curve's knot ticks, then the joints.
std::vector<Vec3> curve_mark_points(const CurveMarks& marks);
// A comparison pane's title (compare_pane_title) at its top left, and its dividers.
void draw_panel_label(const OverlayFrame& o, const std::string& label, const ViewRect& whole);
void draw_axis_triad(const OverlayFrame& o);
void draw_error_text(const ViewRect& rect, const std::string& text);
// The active tool's feedback (picked points and lines, the dashed rubber band, the mark where a
// click acts) and the tangent planes of selected vertices (a disc in the plane, the normal with
// its knob; `hot` is the knob under the cursor, -1 if none).
void draw_tool_overlays(const ViewRect& rect, const Camera& camera, const ToolPreview& preview,
                        const std::vector<PlaneHandle>& planes, int hot, float ui_scale);

}  // namespace pl
