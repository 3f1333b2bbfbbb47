#include "app/cli/arguments.hpp"

#include <charconv>

namespace pl {

Arguments::Arguments(std::span<const std::string> args, const std::set<std::string>& with_value,
                     const std::set<std::string>& flags) {
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (with_value.count(a)) {
      if (i + 1 >= args.size()) throw UsageError("option " + a + " needs a value");
      if (!values_.emplace(a, args[++i]).second) throw UsageError("option " + a + " given twice");
    } else if (flags.count(a)) {
      flags_.insert(a);
    } else if (a.size() > 1 && a[0] == '-') {
      throw UsageError("unknown option " + a);
    } else {
      positional_.push_back(a);
    }
  }
}

std::optional<std::string> Arguments::value(const std::string& option) const {
  auto it = values_.find(option);
  if (it == values_.end()) return std::nullopt;
  return it->second;
}

int Arguments::integer(const std::string& option, int fallback, int lo, int hi) const {
  const auto v = value(option);
  if (!v) return fallback;
  int r = 0;
  const auto [end, ec] = std::from_chars(v->data(), v->data() + v->size(), r);
  if (ec != std::errc() || end != v->data() + v->size() || r < lo || r > hi)
    throw UsageError(option + " takes a whole number from " + std::to_string(lo) + " to " +
                     std::to_string(hi) + ", got \"" + *v + "\"");
  return r;
}

}  // namespace pl
