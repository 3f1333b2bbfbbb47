// The actions on the interior of a network GB face (docs/scene-format.md, "Interior control"):
// raise and lower its degree, reset its free points to their defaults. They act on the selected
// face, or on the face of the selected free point; in the menu bar (Face), the right-click menu
// on a face or point, F1 and the face panel. Each is one Document command; a refusal (a Gregory
// face, a degree out of range) says why and changes nothing. GUI-free, tested through the
// registry.
#pragma once

#include <optional>
#include <string>

#include "app/document/document.hpp"
#include "app/editor/logic/actions.hpp"
#include "app/editor/logic/selection.hpp"
#include "app/editor/logic/selection_actions.hpp"

namespace pl {

// What the face panel shows of a face's interior.
struct InteriorSummary {
  int face = -1;
  bool has_interior = false;  // a GB face; else `why_not` says why there is none
  std::string why_not;
  int degree = 3;
  int free_points = 0;  // how many the face has at its degree
  int moved = 0;        // how many carry an offset
};

// The face the interior actions act on: the only selected face, else the face of the first
// selected free point.
std::optional<int> interior_face(const Scene& scene, const Selection& selection);
std::optional<InteriorSummary> interior_summary(const Scene& scene, int face);

void add_interior_actions(ActionRegistry& actions, Document& doc, Selection& selection, Say say);

}  // namespace pl
