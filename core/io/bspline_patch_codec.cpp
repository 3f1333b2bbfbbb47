// {"type": "bspline", "degree": [p, q], "size": [nu, nv], "knots_u": [...], "knots_v": [...],
//  "points": [nu*nv points]}; points[i*nv+j] is P_ij; absent knots are clamped uniform.
#include "core/io/bspline_patch_codec.hpp"

#include "core/io/classic_codec_util.hpp"
#include "core/patch/bspline_patch.hpp"

namespace pl {

std::unique_ptr<Patch> read_bspline_patch(const JsonNode& node) {
  node.allow_only({"type", "name", "degree", "size", "knots_u", "knots_v", "points"});
  const auto deg = node.at("degree").items(2);
  const int p = deg[0].integer_in(1, kMaxSplineDegree), q = deg[1].integer_in(1, kMaxSplineDegree);
  const auto size = node.at("size").items(2);
  const std::size_t nu = size[0].integer_in(p + 1, 1000), nv = size[1].integer_in(q + 1, 1000);
  const std::vector<double> ku = read_knots(node, "knots_u", p, nu),
                            kv = read_knots(node, "knots_v", q, nv);
  const JsonNode pts = node.at("points");
  pts.items(nu * nv);
  return std::make_unique<BSplinePatch>(p, q, ku, kv, nu, nv, pts.points());
}

void write_bspline_patch(const Patch& patch, nlohmann::json& out) {
  const auto& s = dynamic_cast<const BSplinePatch&>(patch);
  const SplineGrid& g = s.grid();
  out["degree"] = {g.p(), g.q()};
  out["size"] = {g.nu(), g.nv()};
  out["knots_u"] = numbers_json(g.knots_u());
  out["knots_v"] = numbers_json(g.knots_v());
  out["points"] = points_json(s.control_points());
}

}  // namespace pl
