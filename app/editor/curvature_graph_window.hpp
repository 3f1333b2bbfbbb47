// The Curvature Graph window: κ against t of the selected free curve, with its range and the
// knots as ticks under the plot. ImGui code; the graph itself is curvature_graph.hpp's.
#pragma once

#include <optional>

#include "core/scene/scene.hpp"

namespace pl {

// `open` is cleared when the window is closed. `curve` is the selected curve's index, if any.
// Returns true when the window has the keyboard focus (Esc then closes it).
bool draw_curvature_graph_window(bool* open, const Scene& scene, std::optional<int> curve,
                                 float ui_scale);

}  // namespace pl
