// The `curves` entries of a scene (docs/scene-format.md, section Curves): reading with a located
// message for every malformed curve; what a writer writes, with full double precision.
#pragma once

#include <nlohmann/json.hpp>

#include "core/curve/scene_curve.hpp"
#include "core/io/json_node.hpp"

namespace pl {

// `packed_points`: the curve's "points" as the parser packed them (StreamedArray in
// json_node.hpp), the key then holding null; taken over by the curve.
SceneCurve read_curve(const JsonNode& node, std::vector<Vec3>* packed_points = nullptr);
// A curve's keys as the format writes them, in its order: a value (type, name, degree) or one of
// the curve's arrays, left in the curve so that a writer streams it (one curve may hold 400,000
// points: built as JSON they took 50 MB before the first byte was written).
struct CurveKey {
  const char* key;
  nlohmann::json value;
  const std::vector<Vec3>* points = nullptr;
  const std::vector<double>* numbers = nullptr;
};
std::vector<CurveKey> curve_keys(const SceneCurve& curve);
// The same as one JSON object (a curve inside a patch).
nlohmann::json curve_json(const SceneCurve& curve);

}  // namespace pl
