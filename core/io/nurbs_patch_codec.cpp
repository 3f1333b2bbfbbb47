// {"type": "nurbs", ... the keys of "bspline" ..., "weights": [nu*nv positive numbers]}.
#include "core/io/classic_codec_util.hpp"
#include "core/io/patch_codec.hpp"
#include "core/patch/nurbs_patch.hpp"
#include "core/patch/patch_types.hpp"

namespace pl {

namespace {

std::unique_ptr<Patch> read_nurbs_patch(const JsonNode& node) {
  node.allow_only({"type", "name", "degree", "size", "knots_u", "knots_v", "points", "weights"});
  SplineGridJson g = read_spline_grid(node);
  const JsonNode wn = node.at("weights");
  const auto witems = wn.items(g.nu * g.nv);
  std::vector<double> w;
  for (const JsonNode& x : witems) {
    w.push_back(x.number());
    if (!(w.back() > 0)) x.fail("a weight must be positive");
  }
  return std::make_unique<NurbsPatch>(g.p, g.q, g.knots_u, g.knots_v, g.nu, g.nv,
                                      std::move(g.points), std::move(w));
}

void write_nurbs_patch(const Patch& patch, nlohmann::json& out) {
  const auto& s = patch_ref<NurbsPatch>(patch);
  write_spline_grid(s.grid(), s.control_points(), out);
  out["weights"] = numbers_json(s.weights());
}

}  // namespace

const PatchCodec kNurbsPatchCodec{NurbsPatch::kType, read_nurbs_patch, write_nurbs_patch};

}  // namespace pl
