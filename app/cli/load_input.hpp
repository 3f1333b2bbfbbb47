// The FILE argument of the CLI and the options naming schemes: checked before any file is opened.
// The file itself is read by load_scene_file (app/document/scene_file.hpp).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "app/document/scene_file.hpp"
#include "core/scene/scene.hpp"

namespace pl {

// The commands check their FILE's extension with their other arguments: a name that is neither
// .json nor .gbp is wrong usage (UsageError), found before any file is opened.
void check_input_name(const std::string& file);

// Parses --scheme (nullopt when absent); throws UsageError for other values.
std::optional<FaceScheme> parse_scheme_option(const std::optional<std::string>& value);

// "a,b,c" as its items; throws UsageError naming `option` for an empty item.
std::vector<std::string> split_list(const std::string& list, const std::string& option);
// One of comparable_schemes() by keyword, or a list of them; throws UsageError naming `option`,
// the unknown keyword and the allowed ones.
FaceScheme parse_comparable_scheme(const std::string& keyword, const std::string& option);
std::vector<FaceScheme> parse_scheme_list(const std::string& list, const std::string& option);

}  // namespace pl
