// Whether a command line means the editor (`patchlab`, `patchlab FILE`, editor options) or the
// headless CLI (a sub-command, --help, --version). GUI-free and unit-tested.
#pragma once

#include <span>
#include <string>

namespace pl {

bool is_editor_invocation(std::span<const std::string> args);

}  // namespace pl
