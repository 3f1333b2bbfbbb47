#include <iostream>
#include <string>
#include <vector>

#include "app/cli/cli.hpp"
#include "app/editor/editor_main.hpp"
#include "app/cli/editor_invocation.hpp"

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  // `patchlab [FILE]` is the editor; sub-commands and --help/--version are the headless CLI.
  if (pl::is_editor_invocation(args)) return pl::run_editor(args, std::cout, std::cerr);
  return pl::run_cli(args, std::cout, std::cerr);
}
