#include "app/cli/load_input.hpp"

#include "app/cli/arguments.hpp"
#include "core/base/data_error.hpp"
#include "core/io/gbp_io.hpp"
#include "core/io/scene_io.hpp"

namespace pl {

Scene load_input(const std::filesystem::path& path) {
  const std::string ext = path.extension().string();
  if (ext == ".json") return read_scene(path);
  if (ext == ".gbp") {  // a scene with the one explicit GB patch of the file
    Scene scene;
    scene.patches.push_back({"", std::make_shared<GBPatch>(read_gbp(path))});
    return scene;
  }
  throw DataError(path.string(), "", "unknown file type \"" + ext + "\" (expected .json or .gbp)");
}

void check_input_name(const std::string& file) {
  const std::string ext = std::filesystem::path(file).extension().string();
  if (ext != ".json" && ext != ".gbp")
    throw UsageError("FILE is a scene (.json) or a GB net (.gbp), not \"" + file + "\"");
}

std::optional<FaceScheme> parse_scheme_option(const std::optional<std::string>& value) {
  if (!value) return std::nullopt;
  if (*value == "gregory") return FaceScheme::Gregory;
  if (*value == "gb") return FaceScheme::GB;
  throw UsageError("--scheme takes gregory or gb, got \"" + *value + "\"");
}

}  // namespace pl
