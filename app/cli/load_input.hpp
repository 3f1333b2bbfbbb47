// Opens a FILE argument of the CLI: a scene (.json) or a GB patch (.gbp).
#pragma once

#include <filesystem>
#include <optional>

#include "core/scene/scene.hpp"

namespace pl {

// Throws DataError for unreadable or malformed files and unknown extensions.
Scene load_input(const std::filesystem::path& path);

// The commands check their FILE's extension with their other arguments: a name that is neither
// .json nor .gbp is wrong usage (UsageError), found before any file is opened.
void check_input_name(const std::string& file);

// Parses --scheme (nullopt when absent); throws UsageError for other values.
std::optional<FaceScheme> parse_scheme_option(const std::optional<std::string>& value);

}  // namespace pl
