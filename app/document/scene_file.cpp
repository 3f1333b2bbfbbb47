#include "app/document/scene_file.hpp"

#include "core/base/data_error.hpp"
#include "core/cad/cad_curves.hpp"
#include "core/io/gbp_io.hpp"
#include "core/io/obj_curves.hpp"
#include "core/io/scene_io.hpp"
#include "core/patch/patch_types.hpp"

namespace pl {

std::optional<SceneFileType> scene_file_type(const std::filesystem::path& file) {
  const std::string ext = file.extension().string();
  if (ext == ".json") return SceneFileType::Scene;
  if (ext == ".gbp") return SceneFileType::Gbp;
  return std::nullopt;
}

const GBPatch& single_gb_patch(const Scene& scene, const std::string& file) {
  if (scene.network)
    throw DataError(file, "network",
                    "a .gbp holds exactly one gb patch; this scene has a curve network");
  if (scene.patches.size() != 1)
    throw DataError(file, "patches",
                    "a .gbp holds exactly one gb patch; this scene has " +
                        std::to_string(scene.patches.size()) + " explicit patches");
  const auto* gb = patch_as<GBPatch>(scene.patches[0].patch.get());
  if (!gb)
    throw DataError(file, "patches[0]",
                    "a .gbp holds a gb patch; this patch is of type \"" +
                        scene.patches[0].patch->type() + "\"");
  return *gb;
}

bool fits_gbp(const Scene& scene) {
  return !scene.network && scene.patches.size() == 1 &&
         patch_as<GBPatch>(scene.patches[0].patch.get()) != nullptr;
}

void save_scene_file(const std::filesystem::path& file, const Scene& scene) {
  const auto type = scene_file_type(file);
  if (!type)
    throw DataError(file.string(), "",
                    "unknown file type \"" + file.extension().string() +
                        "\": scenes are saved as .json (or .gbp for a single GB patch), the types "
                        "Open and the command line read");
  if (*type == SceneFileType::Gbp)
    write_gbp(file, single_gb_patch(scene, file.string()));
  else
    write_scene(file, scene);
}

Scene load_scene_file(const std::filesystem::path& path) {
  const std::string ext = path.extension().string();
  if (ext == ".json") return read_scene(path);
  if (ext == ".gbp") {  // a scene with the one explicit GB patch of the file
    Scene scene;
    scene.patches.push_back({"", std::make_shared<GBPatch>(read_gbp(path))});
    return scene;
  }
  if (ext == ".obj") {
    Scene scene;
    scene.name = path.stem().string();
    scene.curves = read_obj_curves(path).curves;
    return scene;
  }
  if (cad_format_for(path)) {
    Scene scene;
    scene.name = path.stem().string();
    scene.curves = read_cad_curves(path).curves;
    return scene;
  }
  throw DataError(path.string(), "",
                  "unknown file type \"" + ext +
                      "\" (expected .json, .gbp, or curves from .obj, .step, .stp, .igs, .iges)");
}

const std::vector<std::string>& openable_extensions() {
  static const std::vector<std::string> extensions{".json", ".gbp", ".obj", ".step",
                                                   ".stp",  ".igs", ".iges"};
  return extensions;
}

}  // namespace pl
