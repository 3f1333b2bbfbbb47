// A PatchLab scene (scene-format.md): an optional curve network, explicit patches and free curves.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/curve/scene_curve.hpp"
#include "core/patch/patch.hpp"
#include "core/scene/network.hpp"

namespace pl {

struct ScenePatch {
  std::string name;  // may be empty; then tools call it patch<i>
  std::shared_ptr<Patch> patch;
};

struct Scene {
  std::string name;
  std::optional<Network> network;
  std::vector<ScenePatch> patches;
  std::vector<SceneCurve> curves;  // free curves (scene-format.md, section Curves)
  std::string view_json;           // the editor's "view" object, kept verbatim (empty if absent)
};

}  // namespace pl
