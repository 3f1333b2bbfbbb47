// The actions on the selected free curve (picked by its line, or the curve of a selected curve
// point), as actions of the
// editor's table (menu bar Curve, right-click menu on a point, F1): insert a knot (at the curve
// parameter nearest where the right-click menu was opened, else in the middle of the longest
// span), elevate the degree, split (same parameter), reverse, and turn the selected curves into
// network edges. Each is one Document command; a
// refusal says why in the status bar and changes nothing. GUI-free and unit-tested through the
// registry.
#pragma once

#include <functional>
#include <optional>

#include "app/document/document.hpp"
#include "app/editor/logic/actions.hpp"
#include "app/editor/logic/selection.hpp"
#include "app/editor/logic/selection_actions.hpp"

namespace pl {

// The first selected curve (picked whole or by one of its points), if any.
std::optional<int> selected_curve(const Scene& scene, const Selection& selection);
// Every curve selected whole or by one of its points, each once, in selection order (what To
// Network Edges acts on; Delete takes only whole curves: authoring_actions.hpp).
std::vector<int> curves_of_selection(const Scene& scene, const Selection& selection);
// The parameter of the curve sample nearest to `at` (in space).
double nearest_curve_parameter(const SceneCurve& curve, const Vec3& at);
// The middle of the curve's longest span: where a knot goes when nothing says where.
double default_knot_parameter(const SceneCurve& curve);

struct CurveActionHooks {
  Say say;
  // Where the right-click menu was opened (in space), if it was on something.
  std::function<std::optional<Vec3>()> menu_point = [] { return std::nullopt; };
};

// `doc` and `selection` must outlive the registry's use of the actions.
void add_curve_actions(ActionRegistry& actions, Document& doc, Selection& selection,
                       CurveActionHooks hooks);

}  // namespace pl
