// Opens a FILE argument of the CLI: a scene (.json) or a GB patch (.gbp).
#pragma once

#include <filesystem>
#include <optional>

#include "core/scene/scene.hpp"

namespace pl {

// Throws DataError for unreadable or malformed files and unknown extensions.
Scene load_input(const std::filesystem::path& path);

// Parses --scheme (nullopt when absent); throws UsageError for other values.
std::optional<FaceScheme> parse_scheme_option(const std::optional<std::string>& value);

}  // namespace pl
