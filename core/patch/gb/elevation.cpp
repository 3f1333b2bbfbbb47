#include "core/patch/gb/elevation.hpp"

#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>

#include "core/patch/gb/default_net.hpp"

namespace pl {

namespace {

// Below this central weight at the domain centre, C_0 cannot steer the centre point.
constexpr double kCentralWeightFloor = 1e-6;

// Ribbon i's grid P^i_{j,k} for k = 0 .. l, row l (even d only) being the tensor-product middle
// row that the neighbouring ribbons' middle columns and C_0 make up.
Vec3 extended(const GBPatch& g, int i, int j, int k) {
  const int d = g.degree(), l = g.layers();
  if (k < l) return g.point(i, j, k);
  const int m = d / 2;  // k == l == m: d is even
  if (j < m) return g.point(i - 1, m, j);
  if (j > m) return g.point(i + 1, m, d - j);
  return g.control_point(0);
}

// Tensor-product elevation of ribbon i at the new grid position (j, k) (degree d -> d+1).
Vec3 elevated(const GBPatch& g, int i, int j, int k) {
  const int d = g.degree();
  const double wj = double(j) / (d + 1), wk = double(k) / (d + 1);
  Vec3 q(0);
  for (int a = 0; a <= 1; ++a)
    for (int b = 0; b <= 1; ++b) {
      const double w = (a ? wj : 1 - wj) * (b ? wk : 1 - wk);
      const int jj = j - a, kk = k - b;
      if (w != 0 && jj >= 0 && jj <= d && kk >= 0) q += w * extended(g, i, jj, kk);
    }
  return q;
}

}  // namespace

GBPatch gb_elevate(const GBPatch& patch) {
  const int n = patch.sides(), d = patch.degree(), e = d + 1;
  if (d < 2 || d >= GBPatch::kMaxDegree)
    throw std::invalid_argument("gb_elevate: degree " + std::to_string(d) + " outside 2.." +
                                std::to_string(GBPatch::kMaxDegree - 1));
  std::vector<Vec3> p(GBPatch::point_count(n, e));
  const GBPatch shape(n, e, p);  // for index() only
  for (int k = 0; k < shape.layers(); ++k)
    for (int i = 0; i < n; ++i)
      for (int j = k; j <= e - 1 - k; ++j) p[shape.index(i, j, k)] = elevated(patch, i, j, k);
  GBPatch out(n, e, std::move(p));  // C_0 still 0
  // C_0 through the old surface's centre point (CGF 2016's middle-point interpolation). Where C_0
  // has no weight at the centre (n = 4 with odd d+1: it has no weight anywhere) it takes the
  // default-net position instead.
  std::vector<Jet> phi(out.size());
  out.basis({0, 0}, phi);
  if (std::abs(phi[0].f) <= kCentralWeightFloor) {
    const auto placed = std::make_unique<bool[]>(out.size());
    for (std::size_t k = 1; k < out.size(); ++k) placed[k] = true;
    return gb_default_net(out, std::span<const bool>(placed.get(), out.size()));
  }
  Vec3 rest = patch.evaluate({0, 0}).p;
  for (std::size_t k = 1; k < out.size(); ++k) rest -= phi[k].f * out.control_point(k);
  out.set_control_point(0, rest / phi[0].f);
  return out;
}

}  // namespace pl
