// {"type": "gb", "sides": n, "degree": d, "points": [...]} of scene-format.md; the points in
// .gbp order (central point first), see GBPatch.
#include "core/io/patch_codec.hpp"
#include "core/patch/gb/gb_patch.hpp"
#include "core/patch/patch_types.hpp"

namespace pl {

namespace {

std::unique_ptr<Patch> read_gb_patch(const JsonNode& node) {
  node.allow_only({"type", "name", "sides", "degree", "points"});
  const int n = node.at("sides").integer_in(3, GBPatch::kMaxSides);
  const int d = node.at("degree").integer_in(1, GBPatch::kMaxDegree);
  const JsonNode pts = node.at("points");
  pts.items(GBPatch::point_count(n, d));
  return std::make_unique<GBPatch>(n, d, pts.points());
}

void write_gb_patch(const Patch& patch, nlohmann::json& out) {
  const auto& p = patch_ref<GBPatch>(patch);
  out["sides"] = p.sides();
  out["degree"] = p.degree();
  out["points"] = points_json(p.control_points());
}

}  // namespace

const PatchCodec kGBPatchCodec{GBPatch::kType, read_gb_patch, write_gb_patch};

}  // namespace pl
