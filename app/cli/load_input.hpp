// Opens a FILE argument of the CLI: a scene (.json) or a GB patch (.gbp).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/scene/scene.hpp"

namespace pl {

// Throws DataError for unreadable or malformed files and unknown extensions.
Scene load_input(const std::filesystem::path& path);

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
