// A document's file, read and written: the file types a scene is opened from and saved as, chosen
// by the file name's extension. Curves made elsewhere (OBJ polylines, STEP and IGES edges) open
// as free curves but are never written back there. `.json` is a scene; `.gbp` holds
// one GB patch and nothing else (no names, no network), so a scene goes there only when that is
// all it has. Any other extension is refused: a scene saved as "part.jsonn" would be invisible
// to Open and to the command line.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/patch/gb/gb_patch.hpp"
#include "core/scene/scene.hpp"

namespace pl {

enum class SceneFileType { Scene, Gbp };

// The type of a file name (".json" or ".gbp"), nullopt otherwise.
std::optional<SceneFileType> scene_file_type(const std::filesystem::path& file);

// The scene's one GB patch; throws DataError(file, ...) saying why a .gbp cannot hold the scene.
const GBPatch& single_gb_patch(const Scene& scene, const std::string& file);
bool fits_gbp(const Scene& scene);

// Reads a scene (.json), a GB patch (.gbp) as a scene of that one patch, or the curves of a
// Wavefront OBJ (its polylines) or of a STEP or IGES file (its edges) as a scene of free curves.
// Throws DataError for unreadable or malformed files and unknown extensions.
Scene load_scene_file(const std::filesystem::path& file);
// The extensions load_scene_file reads (lower case, with the dot), for Open's file list.
const std::vector<std::string>& openable_extensions();

// Writes the scene atomically as the extension says. Throws DataError naming the file: an
// unknown extension, a scene a .gbp cannot hold, or a failed write (the old file is kept).
void save_scene_file(const std::filesystem::path& file, const Scene& scene);

}  // namespace pl
