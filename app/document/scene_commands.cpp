#include "app/document/scene_commands.hpp"

#include <algorithm>

#include "core/patch/flip_orientation.hpp"
#include "core/scene/network_edit.hpp"

namespace pl {

void FlipPatchesCommand::apply(Scene& scene) {
  std::sort(patches_.begin(), patches_.end());
  patches_.erase(std::unique(patches_.begin(), patches_.end()), patches_.end());
  if (patches_.empty()) throw EditRefused("no patch to flip");
  for (int p : patches_) {
    if (p < 0 || p >= int(scene.patches.size()))
      throw EditRefused("patch " + std::to_string(p) + " does not exist");
    const Patch& patch = *scene.patches[p].patch;
    if (!can_flip_orientation(patch))
      throw EditRefused("patch " + std::to_string(p) + " (" + patch.type() +
                        ") cannot be flipped: its construction fixes which piece lies on which "
                        "side");
    // A new patch object: the one before stays untouched in the undo history.
    scene.patches[p].patch = std::shared_ptr<Patch>(flipped_orientation(patch).patch);
  }
}

std::string FlipPatchesCommand::label() const {
  if (patches_.size() == 1) return "flip patch " + std::to_string(patches_[0]);
  return "flip " + std::to_string(patches_.size()) + " patches";
}

}  // namespace pl
