// The comparison's table of quality figures under the panes (CompareFigures' last result): one
// row per face and scheme, the columns of `patchlab compare`. ImGui code.
#pragma once

#include "app/editor/logic/compare_figures.hpp"
#include "app/editor/logic/view_math.hpp"

namespace pl {

// Draws the table in `strip` (window pixels). `stale`: the figures are of an earlier state of
// the document (a drag or a recomputation is under way).
void draw_figures_table(const ViewRect& strip, const CompareFigures& figures, bool stale);

}  // namespace pl
