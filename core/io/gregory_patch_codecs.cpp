// {"type": "gregory-quad", "points": [20 points]} and {"type": "gregory-tri", "points": [18
// points]}; point order in docs/patch-types.md and the patch headers.
#include "core/io/patch_codec.hpp"
#include "core/patch/gregory_quad.hpp"
#include "core/patch/gregory_tri.hpp"

namespace pl {

namespace {

std::unique_ptr<Patch> read_gregory_quad_patch(const JsonNode& node) {
  node.allow_only({"type", "name", "points"});
  const JsonNode pts = node.at("points");
  pts.items(GregoryQuadPatch::kPointCount);
  return std::make_unique<GregoryQuadPatch>(pts.points());
}

void write_gregory_quad_patch(const Patch& patch, nlohmann::json& out) {
  out["points"] = points_json(dynamic_cast<const GregoryQuadPatch&>(patch).control_points());
}

std::unique_ptr<Patch> read_gregory_tri_patch(const JsonNode& node) {
  node.allow_only({"type", "name", "points"});
  const JsonNode pts = node.at("points");
  pts.items(GregoryTriPatch::kPointCount);
  return std::make_unique<GregoryTriPatch>(pts.points());
}

void write_gregory_tri_patch(const Patch& patch, nlohmann::json& out) {
  out["points"] = points_json(dynamic_cast<const GregoryTriPatch&>(patch).control_points());
}

}  // namespace

const PatchCodec kGregoryQuadCodec{GregoryQuadPatch::kType, read_gregory_quad_patch,
                                   write_gregory_quad_patch};

const PatchCodec kGregoryTriCodec{GregoryTriPatch::kType, read_gregory_tri_patch,
                                  write_gregory_tri_patch};

}  // namespace pl
