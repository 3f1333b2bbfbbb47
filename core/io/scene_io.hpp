// Scene files (scene-format.md): reading with full validation, writing atomically.
#pragma once

#include <filesystem>
#include <string>

#include "core/scene/scene.hpp"

namespace pl {

// Parses and validates a scene; every error is a DataError naming `source` and a JSON path.
// Never returns half a scene.
Scene parse_scene(const std::string& text, const std::string& source);
Scene read_scene(const std::filesystem::path& path);

// Full double round-trip precision.
std::string scene_to_json(const Scene& scene);
void write_scene(const std::filesystem::path& path, const Scene& scene);  // atomic

}  // namespace pl
