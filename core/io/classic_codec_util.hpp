// Helpers shared by the classic-type codecs (B-spline, NURBS, Coons network, ...).
#pragma once

#include <stdexcept>
#include <vector>

#include "core/io/json_node.hpp"
#include "core/math/bspline_basis.hpp"
#include "core/patch/spline_grid.hpp"

namespace pl {

inline std::vector<double> read_numbers(const JsonNode& node) {
  std::vector<double> r;
  for (const JsonNode& n : node.items()) r.push_back(n.number());
  return r;
}

inline nlohmann::json numbers_json(const std::vector<double>& v) {
  return nlohmann::json(v);
}

// Knots under `key`, or clamped uniform knots when the key is absent; an invalid knot vector is
// reported at the key's path.
std::vector<double> read_knots(const JsonNode& node, const char* key, int degree,
                               std::size_t count);

// The keys B-spline and NURBS patches share: "degree", "size", "knots_u", "knots_v", "points".
struct SplineGridJson {
  int p = 0, q = 0;
  std::size_t nu = 0, nv = 0;
  std::vector<double> knots_u, knots_v;
  std::vector<Vec3> points;
};
SplineGridJson read_spline_grid(const JsonNode& node);
void write_spline_grid(const SplineGrid& grid, const std::vector<Vec3>& points,
                       nlohmann::json& out);

}  // namespace pl
