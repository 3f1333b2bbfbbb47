// The actions on explicit patches that need only the document and the selection: flipping a
// patch's orientation (the front becomes the back). Registered into the editor's ActionRegistry
// (menu, right-click menu, F1); unit-tested through the registry.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "app/document/document.hpp"
#include "app/editor/logic/actions.hpp"
#include "app/editor/logic/selection.hpp"

namespace pl {

// The patches Flip Orientation acts on: the selected patches and the patches of selected points,
// else, with nothing of that selected, the scene's only patch when it has no network faces (an
// opened .gbp).
std::vector<int> patches_to_flip(const Scene& scene, const Selection& selection);

// `doc` and `selection` must outlive the registry's use of the actions; `say` shows a message
// (the status bar).
void add_patch_actions(ActionRegistry& actions, Document& doc, Selection& selection,
                       std::function<void(const std::string&)> say);

}  // namespace pl
