// {"type": "bezier", "degree": [m, n], "points": [...]} of scene-format.md.
#include "core/io/patch_codec.hpp"
#include "core/patch/bezier_patch.hpp"
#include "core/patch/patch_types.hpp"

namespace pl {

namespace {

std::unique_ptr<Patch> read_bezier_patch(const JsonNode& node) {
  node.allow_only({"type", "name", "degree", "points"});
  const auto deg = node.at("degree").items(2);
  const int m = deg[0].integer_in(1, 30), n = deg[1].integer_in(1, 30);
  const JsonNode pts = node.at("points");
  pts.items((m + 1) * (n + 1));
  return std::make_unique<BezierPatch>(m, n, pts.points());
}

void write_bezier_patch(const Patch& patch, nlohmann::json& out) {
  const auto& p = patch_ref<BezierPatch>(patch);
  out["degree"] = {p.degree_u(), p.degree_v()};
  out["points"] = points_json(p.control_points());
}

}  // namespace

const PatchCodec kBezierPatchCodec{BezierPatch::kType, read_bezier_patch, write_bezier_patch};

}  // namespace pl
