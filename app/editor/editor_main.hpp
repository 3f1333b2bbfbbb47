// `patchlab [FILE] [--bench-drag [--busy]] [--debug-point NAME] [--size WxH]`: the editor's entry
// point.
#pragma once

#include <ostream>
#include <span>
#include <string>

namespace pl {

int run_editor(std::span<const std::string> args, std::ostream& out, std::ostream& err);

}  // namespace pl
