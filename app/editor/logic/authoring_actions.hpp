// The authoring commands that act on the selection, as actions of the editor's table (menu bar,
// right-click menu, keys, F1): delete (network elements and free curves), add an edge between two
// selected vertices, make a face of the selected chain, fill holes, split the selected edge, and
// fix or fit the tangent planes of the selected vertices. Each is one Document command (one undo
// step); a refused request says why in the status bar and changes nothing. After a command the
// selection names the same objects in the new numbering (what a delete removed is dropped) or the
// new object. GUI-free and unit-tested through the registry.
#pragma once

#include <functional>
#include <optional>

#include "app/document/document.hpp"
#include "app/editor/logic/actions.hpp"
#include "app/editor/logic/selection.hpp"
#include "app/editor/logic/selection_actions.hpp"

namespace pl {

struct AuthoringHooks {
  Say say;
  // The direction to the viewer: a new face's normal follows it where no neighbour decides.
  std::function<Vec3()> towards = [] { return Vec3(0, 0, 1); };
  // The curve parameter of the edge where the right-click menu was opened on it, if it was.
  std::function<std::optional<double>(int edge)> split_parameter = [](int) { return std::nullopt; };
};

// `doc` and `selection` must outlive the registry's use of the actions.
void add_authoring_actions(ActionRegistry& actions, Document& doc, Selection& selection,
                           AuthoringHooks hooks);

// The network vertices, edges and faces selected (in selection order, existing ones only).
struct SelectedElements {
  std::vector<int> vertices, edges, faces;
  bool empty() const { return vertices.empty() && edges.empty() && faces.empty(); }
};
SelectedElements selected_elements(const Scene& scene, const Selection& selection);
// The free curves selected whole (in selection order, existing ones only).
std::vector<int> selected_curves(const Scene& scene, const Selection& selection);

}  // namespace pl
