// The `patchlab` command line (docs/cli.md): dispatches to the sub-commands.
#pragma once

#include <ostream>
#include <span>
#include <string>

namespace pl {

// Exit codes of the CLI contract.
constexpr int kExitOk = 0, kExitBadInput = 1, kExitUsage = 2;

int run_cli(std::span<const std::string> args, std::ostream& out, std::ostream& err);

}  // namespace pl
