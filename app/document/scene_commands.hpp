// Commands on the scene as a whole and on its explicit patches.
#pragma once

#include <string>
#include <vector>

#include "app/document/command.hpp"

namespace pl {

// Flips the orientation of explicit patches (flipped_orientation: the same surface with the
// normal reversed, the control points permuted), so the side shown as the front becomes the
// back. One undo step for all of them; undo restores the patches as they were, bit for bit.
// Refused (EditRefused, nothing changes) for a patch that does not exist or whose type cannot
// be flipped (composite pair-join and gap-fill patches).
class FlipPatchesCommand final : public Command {
 public:
  explicit FlipPatchesCommand(std::vector<int> patches) : patches_(std::move(patches)) {}
  void apply(Scene& scene) override;
  std::string label() const override;

 private:
  std::vector<int> patches_;
};

// Replaces the whole scene: unsaved work recovered after a crash, applied on top of the file it
// was an edit of, so the document is dirty and undo goes back to the file as saved.
class ReplaceSceneCommand final : public Command {
 public:
  ReplaceSceneCommand(Scene scene, std::string label)
      : scene_(std::move(scene)), label_(std::move(label)) {}
  void apply(Scene& scene) override { scene = scene_; }
  std::string label() const override { return label_; }

 private:
  Scene scene_;
  std::string label_;
};

}  // namespace pl
