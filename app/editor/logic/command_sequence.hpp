// Several commands as one undo step (one scheme change for every selected face, the planes of
// several vertices fixed at once). They apply in order to the same copy of the scene, so a
// refusal of any leaves the document unchanged.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "app/document/command.hpp"

namespace pl {

class CommandSequence final : public Command {
 public:
  CommandSequence(std::string label, std::vector<std::unique_ptr<Command>> commands)
      : label_(std::move(label)), commands_(std::move(commands)) {}
  void apply(Scene& scene) override {
    for (const auto& c : commands_) c->apply(scene);
  }
  std::string label() const override { return label_; }

 private:
  std::string label_;
  std::vector<std::unique_ptr<Command>> commands_;
};

// The commands as one step: the single command itself, or a sequence labelled `label`.
std::unique_ptr<Command> as_one_step(std::string label,
                                     std::vector<std::unique_ptr<Command>> commands);

}  // namespace pl
