// The actions that work on the selection and need nothing but the document and the selection:
// selecting related objects (a face's points and edges, an edge's faces, everything) and the
// face scheme. Registered into the editor's ActionRegistry, from which the menu bar, the
// right-click menu, the keys and F1 are drawn; unit-tested through the registry.
#pragma once

#include "app/document/document.hpp"
#include "app/editor/logic/actions.hpp"
#include "app/editor/logic/selection.hpp"

namespace pl {

// A line for the status bar: what an action did, or why it was refused.
using Say = std::function<void(const std::string&)>;

// `doc` and `selection` must outlive the registry's use of the actions.
void add_selection_actions(ActionRegistry& actions, Document& doc, Selection& selection,
                           const Say& say = {});

}  // namespace pl
