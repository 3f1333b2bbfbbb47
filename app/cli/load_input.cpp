#include "app/cli/load_input.hpp"

#include "app/cli/arguments.hpp"
#include "core/base/data_error.hpp"
#include "core/io/gbp_io.hpp"
#include "core/io/scene_io.hpp"
#include "core/scene/network_edit.hpp"

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

std::optional<FaceScheme> parse_scheme_option(const std::optional<std::string>& value) {
  if (!value) return std::nullopt;
  if (const auto s = parse_scheme_keyword(*value); s && *s != FaceScheme::Auto) return s;
  throw UsageError("--scheme takes one of " + face_scheme_keywords() + ", got \"" + *value + "\"");
}

}  // namespace pl
