#include "app/editor/logic/patch_actions.hpp"

#include <algorithm>

#include "app/document/scene_commands.hpp"
#include "core/patch/flip_orientation.hpp"
#include "core/scene/network_edit.hpp"

namespace pl {

std::vector<int> patches_to_flip(const Scene& scene, const Selection& selection) {
  std::vector<int> r;
  for (const SelectionItem& i : selection.items()) {
    if (!item_exists(scene, i)) continue;
    if (i.kind == SelectionItem::Kind::Patch) r.push_back(i.index);
    if (i.kind == SelectionItem::Kind::Point && i.point.kind == PointRef::Kind::PatchPoint)
      r.push_back(i.point.object);
  }
  const bool faces = scene.network && !scene.network->faces.empty();
  if (r.empty() && scene.patches.size() == 1 && !faces) r.push_back(0);
  std::sort(r.begin(), r.end());
  r.erase(std::unique(r.begin(), r.end()), r.end());
  return r;
}

void add_patch_actions(ActionRegistry& actions, Document& doc, Selection& selection,
                       std::function<void(const std::string&)> say) {
  Action flip = make_action(
      "patch.flip", "Edit", "Flip Patch Orientation", {},
      "flip the selected patches (or the only one): the same surface, front and back swapped",
      nullptr);
  flip.separator_before = true;
  flip.context = context_bit(ContextTarget::Patch) | context_bit(ContextTarget::Point) |
                 context_bit(ContextTarget::Empty);
  flip.enabled = [&doc, &selection] {
    const std::vector<int> p = patches_to_flip(doc.scene(), selection);
    return !p.empty() && std::all_of(p.begin(), p.end(), [&](int i) {
      return can_flip_orientation(*doc.scene().patches[i].patch);
    });
  };
  flip.run = [&doc, &selection, say](const std::optional<KeyChord>&) {
    const std::vector<int> targets = patches_to_flip(doc.scene(), selection);
    if (targets.empty()) return;
    // Where each point goes, from the patches before the flip (the command's own permutation).
    std::vector<std::vector<std::size_t>> old;
    for (int p : targets)
      if (can_flip_orientation(*doc.scene().patches[p].patch))
        old.push_back(flipped_orientation(*doc.scene().patches[p].patch).old_index);
    std::string label;
    try {
      label = doc.execute(std::make_unique<FlipPatchesCommand>(targets));
    } catch (const EditRefused& e) {
      if (say) say(e.what());
      return;
    }
    // Selected points stay on the same points of the surface: the flip permutes them
    // (point k of a flipped patch was point old[k]).
    std::vector<SelectionItem> items = selection.items();
    for (SelectionItem& i : items) {
      if (i.kind != SelectionItem::Kind::Point || i.point.kind != PointRef::Kind::PatchPoint ||
          !std::binary_search(targets.begin(), targets.end(), i.point.object))
        continue;
      const auto& o =
          old[std::lower_bound(targets.begin(), targets.end(), i.point.object) - targets.begin()];
      const auto k = std::find(o.begin(), o.end(), std::size_t(i.point.index));
      if (k != o.end()) i.point.index = int(k - o.begin());
    }
    selection.set(std::move(items));
    if (say) say(label);
  };
  actions.add(std::move(flip));
}

}  // namespace pl
