// {"type": "gap-fill", "q": {B-spline keys}, "r": {B-spline keys}}: each of q and r has the keys
// of a "bspline" entry (degree, size, knots_u, knots_v, points); see gap_fill_patch.hpp.
#include "core/io/patch_codec.hpp"
#include "core/patch/bspline_patch.hpp"
#include "core/patch/gap_fill_patch.hpp"
#include "core/patch/patch_types.hpp"

namespace pl {

namespace {

std::unique_ptr<Patch> read_gap_fill(const JsonNode& node) {
  node.allow_only({"type", "name", "q", "r"});
  const auto q = kBSplinePatchCodec.read(node.at("q"));
  const auto r = kBSplinePatchCodec.read(node.at("r"));
  return std::make_unique<GapFillPatch>(patch_ref<BSplinePatch>(*q), patch_ref<BSplinePatch>(*r));
}

void write_gap_fill(const Patch& patch, nlohmann::json& out) {
  const auto& g = patch_ref<GapFillPatch>(patch);
  kBSplinePatchCodec.write(g.q(), out["q"]);
  kBSplinePatchCodec.write(g.r(), out["r"]);
}

}  // namespace

const PatchCodec kGapFillCodec{GapFillPatch::kType, read_gap_fill, write_gap_fill};

}  // namespace pl
