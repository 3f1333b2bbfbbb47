// {"type": "interpolating", "points": [16 points]}: points[i*4+j] is hit at (u,v) = (i/3, j/3).
#include "core/io/patch_codec.hpp"
#include "core/patch/interpolating_patch.hpp"

namespace pl {

namespace {

std::unique_ptr<Patch> read_interpolating_patch(const JsonNode& node) {
  node.allow_only({"type", "name", "points"});
  const JsonNode pts = node.at("points");
  pts.items(16);
  return std::make_unique<InterpolatingPatch>(pts.points());
}

void write_interpolating_patch(const Patch& patch, nlohmann::json& out) {
  out["points"] = points_json(patch.control_points());
}

}  // namespace

const PatchCodec kInterpolatingPatchCodec{InterpolatingPatch::kType, read_interpolating_patch,
                                          write_interpolating_patch};

}  // namespace pl
