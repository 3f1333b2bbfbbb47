// What the sub-commands make of a scene, once their arguments are parsed: the mesh file of
// `export`, the report of `analyze`, the image of `render`. The command line and the Python module
// (app/python) call these same functions, so both give the same output, bounds and messages.
// Every function throws DataError naming `source` (the scene's file) for bad input.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "app/cli/checked_scene.hpp"
#include "core/analysis/scene_analysis.hpp"
#include "core/eval/scene_surfaces.hpp"
#include "render/display_settings.hpp"
#include "render/image.hpp"

namespace pl {

// `export FILE -o TARGET` for a mesh format (.obj, .ply, .off, .stl).
struct MeshExportCount {
  std::size_t patches = 0, curves = 0;
};
// What `export` prints: "wrote 2 patch(es) and 1 curve(s) to TARGET\n".
std::string mesh_export_summary(const MeshExportCount& count, const std::string& target);
MeshExportCount export_mesh_file(const Scene& scene, const std::filesystem::path& target,
                                 int density, std::optional<FaceScheme> scheme,
                                 const std::string& source);

// `analyze FILE` (report_to_json / report_to_text print it).
SceneReport analyze_input(const Scene& scene, int density, std::optional<FaceScheme> scheme,
                          const std::string& source);

// `render FILE`. Throws DataError for bad input (a view that is neither a preset nor a readable
// camera file included), GlContextError or std::runtime_error when drawing fails.
inline constexpr int kMaxImageSide = 4096;  // pixels, either side
struct RenderJob {
  int width = 1600, height = 1200;
  int density = 32;
  std::optional<FaceScheme> scheme;
  bool compare = false;  // the compared schemes side by side (needs a network; no scheme)
  std::vector<FaceScheme> compared{FaceScheme::Gregory, FaceScheme::GB};
  DisplaySettings settings;
  std::optional<std::string> view;  // a preset name or a camera file; none: the default view
};
struct RenderedImage {
  Image image;
  std::size_t patches = 0;  // the surfaces drawn, in every panel
};
RenderedImage render_scene_image(const Scene& scene, const RenderJob& job,
                                 const std::string& source);

}  // namespace pl
