// {"type": "bspline", "degree": [p, q], "size": [nu, nv], "knots_u": [...], "knots_v": [...],
//  "points": [nu*nv points]}; points[i*nv+j] is P_ij; absent knots are clamped uniform.
#include "core/io/classic_codec_util.hpp"
#include "core/io/patch_codec.hpp"
#include "core/patch/bspline_patch.hpp"
#include "core/patch/patch_types.hpp"

namespace pl {

namespace {

std::unique_ptr<Patch> read_bspline_patch(const JsonNode& node) {
  node.allow_only({"type", "name", "degree", "size", "knots_u", "knots_v", "points"});
  SplineGridJson g = read_spline_grid(node);
  return std::make_unique<BSplinePatch>(g.p, g.q, g.knots_u, g.knots_v, g.nu, g.nv,
                                        std::move(g.points));
}

void write_bspline_patch(const Patch& patch, nlohmann::json& out) {
  const auto& s = patch_ref<BSplinePatch>(patch);
  write_spline_grid(s.grid(), s.control_points(), out);
}

}  // namespace

const PatchCodec kBSplinePatchCodec{BSplinePatch::kType, read_bspline_patch, write_bspline_patch};

}  // namespace pl
