#include "core/io/classic_codec_util.hpp"

#include "core/curve/bspline_curve.hpp"

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

}  // namespace pl
