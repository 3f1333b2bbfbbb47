#include "app/cli/load_input.hpp"

#include "app/cli/arguments.hpp"
#include "core/analysis/compared_schemes.hpp"
#include "core/base/data_error.hpp"
#include "core/scene/network_edit.hpp"

namespace pl {

void check_input_name(const std::string& file) {
  const std::string ext = std::filesystem::path(file).extension().string();
  if (ext != ".json" && ext != ".gbp")
    throw UsageError("FILE is a scene (.json) or a GB net (.gbp), not \"" + file + "\"");
}

std::optional<FaceScheme> parse_scheme_option(const std::optional<std::string>& value) {
  if (!value) return std::nullopt;
  if (const auto s = parse_scheme_keyword(*value); s && *s != FaceScheme::Auto) return s;
  throw UsageError("--scheme takes one of " + face_scheme_keywords() + ", got \"" + *value + "\"");
}

std::vector<std::string> split_list(const std::string& list, const std::string& option) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = list.find(',', start);
    out.push_back(
        list.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (out.back().empty()) throw UsageError(option + " has an empty item in \"" + list + "\"");
    if (comma == std::string::npos) return out;
    start = comma + 1;
  }
}

FaceScheme parse_comparable_scheme(const std::string& keyword, const std::string& option) {
  if (const auto s = comparable_scheme(keyword)) return *s;
  throw UsageError(option + ": unknown scheme \"" + keyword +
                   "\" (allowed: " + comparable_scheme_keywords() + ")");
}

std::vector<FaceScheme> parse_scheme_list(const std::string& list, const std::string& option) {
  std::vector<FaceScheme> out;
  for (const std::string& k : split_list(list, option))
    out.push_back(parse_comparable_scheme(k, option));
  return out;
}

}  // namespace pl
