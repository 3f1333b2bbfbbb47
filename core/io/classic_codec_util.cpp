#include "core/io/classic_codec_util.hpp"

#include "core/curve/bspline_curve.hpp"
#include "core/io/patch_codec.hpp"

namespace pl {

std::vector<double> read_knots(const JsonNode& node, const char* key, int degree,
                               std::size_t count) {
  const auto k = node.find(key);
  if (!k) return BSplineCurve::clamped_uniform_knots(degree, count);
  std::vector<double> knots = read_numbers(*k);
  try {
    validate_knots(degree, knots, count);
  } catch (const std::invalid_argument& e) {
    k->fail(e.what());
  }
  return knots;
}

SplineGridJson read_spline_grid(const JsonNode& node) {
  SplineGridJson g;
  const auto deg = node.at("degree").items(2);
  g.p = deg[0].integer_in(1, kMaxSplineDegree);
  g.q = deg[1].integer_in(1, kMaxSplineDegree);
  const auto size = node.at("size").items(2);
  g.nu = size[0].integer_in(g.p + 1, 1000);
  g.nv = size[1].integer_in(g.q + 1, 1000);
  g.knots_u = read_knots(node, "knots_u", g.p, g.nu);
  g.knots_v = read_knots(node, "knots_v", g.q, g.nv);
  const JsonNode pts = node.at("points");
  pts.items(g.nu * g.nv);
  g.points = pts.points();
  return g;
}

void write_spline_grid(const SplineGrid& grid, const std::vector<Vec3>& points,
                       nlohmann::json& out) {
  out["degree"] = {grid.p(), grid.q()};
  out["size"] = {grid.nu(), grid.nv()};
  out["knots_u"] = numbers_json(grid.knots_u());
  out["knots_v"] = numbers_json(grid.knots_v());
  out["points"] = points_json(points);
}

}  // namespace pl
