#include "core/patch/gb/ribbon_elevation.hpp"

#include <stdexcept>
#include <string>

#include "core/math/bernstein.hpp"

namespace pl {

namespace {

int checked_side(const GBRibbonPatch& patch, int side) {
  if (side < 0 || side >= patch.sides())
    throw std::invalid_argument("ribbon elevation: side " + std::to_string(side) + " of " +
                                std::to_string(patch.sides()));
  return side;
}

}  // namespace

GBRibbonPatch gb_ribbon_elevate(const GBRibbonPatch& patch, int side) {
  auto ribbons = patch.ribbons();
  auto& rows = ribbons[checked_side(patch, side)];
  const int d = patch.degree(side);
  if (d >= GBRibbonPatch::kMaxDegree)
    throw std::invalid_argument("ribbon elevation: side " + std::to_string(side) + " has degree " +
                                std::to_string(d) + ", the limit is " +
                                std::to_string(GBRibbonPatch::kMaxDegree));
  for (auto& row : rows) {
    std::vector<Vec3> up(d + 2);
    up[0] = row[0];
    up[d + 1] = row[d];
    for (int j = 1; j <= d; ++j) {
      const double w = double(j) / (d + 1);
      up[j] = w * row[j - 1] + (1 - w) * row[j];
    }
    row = std::move(up);
  }
  return GBRibbonPatch(patch.polygon(), ribbons);
}

std::vector<std::vector<Vec3>> ribbon_with_layer(const std::vector<std::vector<Vec3>>& in) {
  auto rows = in;
  const int l = static_cast<int>(rows.size()), m = 2 * l - 1;
  std::vector<Vec3> next(rows[l - 1].size());
  for (std::size_t j = 0; j < next.size(); ++j) next[j] = 2.0 * rows[l - 1][j] - rows[l - 2][j];
  rows.push_back(std::move(next));
  std::vector<std::vector<Vec3>> out(l + 1, std::vector<Vec3>(rows[0].size(), Vec3(0)));
  for (int k = 0; k <= l; ++k)
    for (int r = 0; r <= 2 && r <= k; ++r) {
      const double w = binomial(2, r) * binomial(m, k - r) / binomial(m + 2, k);
      for (std::size_t j = 0; j < rows[0].size(); ++j) out[k][j] += w * rows[k - r][j];
    }
  return out;
}

GBRibbonPatch gb_ribbon_add_layer(const GBRibbonPatch& patch, int side) {
  auto ribbons = patch.ribbons();
  const int l = patch.layers(checked_side(patch, side));
  if (l >= GBRibbonPatch::kMaxLayers)
    throw std::invalid_argument("ribbon elevation: side " + std::to_string(side) + " has " +
                                std::to_string(l) + " layers, the limit is " +
                                std::to_string(GBRibbonPatch::kMaxLayers));
  ribbons[side] = ribbon_with_layer(ribbons[side]);
  return GBRibbonPatch(patch.polygon(), ribbons);
}

}  // namespace pl
