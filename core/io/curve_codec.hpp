// The `curves` entries of a scene (docs/scene-format.md, section Curves): reading with a located
// message for every malformed curve, writing with full double precision.
#pragma once

#include <nlohmann/json.hpp>

#include "core/curve/scene_curve.hpp"
#include "core/io/json_node.hpp"

namespace pl {

SceneCurve read_curve(const JsonNode& node);
nlohmann::json curve_json(const SceneCurve& curve);

}  // namespace pl
