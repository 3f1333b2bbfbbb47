// The headless sub-commands. Each returns an exit code; DataError and UsageError are handled by
// run_cli.
#pragma once

#include <ostream>
#include <span>
#include <string>

namespace pl {

struct Command {
  const char* name;
  const char* usage;  // the argument synopsis after the name
  int (*run)(std::span<const std::string> args, std::ostream& out, std::ostream& err);
};

std::span<const Command> commands();

int run_export(std::span<const std::string> args, std::ostream& out, std::ostream& err);
int run_analyze(std::span<const std::string> args, std::ostream& out, std::ostream& err);
int run_compare(std::span<const std::string> args, std::ostream& out, std::ostream& err);
int run_convert(std::span<const std::string> args, std::ostream& out, std::ostream& err);
int run_render(std::span<const std::string> args, std::ostream& out, std::ostream& err);
int run_gbnet(std::span<const std::string> args, std::ostream& out, std::ostream& err);
int run_sample(std::span<const std::string> args, std::ostream& out, std::ostream& err);

}  // namespace pl
