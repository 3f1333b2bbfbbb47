#include "app/editor/logic/command_sequence.hpp"

namespace pl {

std::unique_ptr<Command> as_one_step(std::string label,
                                     std::vector<std::unique_ptr<Command>> commands) {
  if (commands.size() == 1) return std::move(commands[0]);
  return std::make_unique<CommandSequence>(std::move(label), std::move(commands));
}

}  // namespace pl
