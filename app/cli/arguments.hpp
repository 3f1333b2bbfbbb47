// Parses "FILE -o OUT --flag --key VALUE" argument lists against a declared option set.
#pragma once

#include <map>
#include <optional>
#include <set>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace pl {

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class Arguments {
 public:
  // with_value: options that take a value ("-o", "--size"); flags: options that do not.
  Arguments(std::span<const std::string> args, const std::set<std::string>& with_value,
            const std::set<std::string>& flags);

  const std::vector<std::string>& positional() const { return positional_; }
  std::optional<std::string> value(const std::string& option) const;
  bool flag(const std::string& option) const { return flags_.count(option) > 0; }
  // An integer option within [lo, hi], or the default.
  int integer(const std::string& option, int fallback, int lo, int hi) const;

 private:
  std::vector<std::string> positional_;
  std::map<std::string, std::string> values_;
  std::set<std::string> flags_;
};

}  // namespace pl
