#include <iostream>
#include <string>
#include <vector>

#include "app/cli/cli.hpp"

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  return pl::run_cli(args, std::cout, std::cerr);
}
