#include "app/cli/editor_invocation.hpp"

#include "app/cli/commands.hpp"

namespace pl {

bool is_editor_invocation(std::span<const std::string> args) {
  if (args.empty()) return true;
  const std::string& a = args[0];
  if (a == "--help" || a == "-h" || a == "--version") return false;
  for (const Command& c : commands())
    if (a == c.name) return false;
  // A file name or an editor option. Other words stay with the CLI, which reports them as
  // unknown commands.
  return a.rfind("--", 0) == 0 || a.find('.') != std::string::npos ||
         a.find('/') != std::string::npos;
}

}  // namespace pl
