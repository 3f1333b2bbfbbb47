#include "core/patch/gregory_tri.hpp"

#include <array>
#include <cassert>
#include <stdexcept>

#include "core/patch/twin_weight.hpp"

namespace pl {

namespace {

// Powers 0..4 of a barycentric coordinate jet.
std::array<Jet, 5> powers(const Jet& x) {
  std::array<Jet, 5> p;
  p[0] = Jet(1.0);
  for (int i = 1; i < 5; ++i) p[i] = p[i - 1] * x;
  return p;
}

double multinomial4(int i, int j, int k) {
  constexpr double fact[5] = {1, 1, 2, 6, 24};
  return fact[4] / (fact[i] * fact[j] * fact[k]);
}

}  // namespace

GregoryTriPatch::GregoryTriPatch(std::vector<Vec3> points) : PatchType(std::move(points)) {
  if (points_.size() != kPointCount)
    throw std::invalid_argument("a triangular Gregory patch needs 18 points, got " +
                                std::to_string(points_.size()));
}

ControlPointKind GregoryTriPatch::kind(std::size_t k) const {
  return k < 12 ? ControlPointKind::Boundary : ControlPointKind::Twin;
}

void GregoryTriPatch::basis(Vec2 x, std::span<Jet> out) const {
  assert(out.size() == kPointCount);
  const Jet b = Jet::u(x.x), c = Jet::v(x.y);
  const Jet a = Jet(1.0 - x.x - x.y, -1, -1, 0, 0, 0);
  const auto pa = powers(a), pb = powers(b), pc = powers(c);
  const auto bern = [&](int i, int j, int k) {
    return multinomial4(i, j, k) * (pa[i] * pb[j] * pc[k]);
  };
  for (int j = 0; j < 4; ++j) {
    out[boundary_index(0, j)] = bern(4 - j, j, 0);
    out[boundary_index(1, j)] = bern(0, 4 - j, j);
    out[boundary_index(2, j)] = bern(j, 0, 4 - j);
  }
  const auto split = [&](const Jet& g, std::size_t ta, const Jet& wa, std::size_t tb,
                         const Jet& wb) {
    const Jet r = twin_weight(wa, wb);
    out[ta] = g * r;
    out[tb] = g * (1.0 - r);
  };
  const Jet ma = 1.0 - a, mb = 1.0 - b, mc = 1.0 - c;
  split(bern(2, 1, 1), twin_index(0, 0), mc * b, twin_index(2, 1), mb * c);
  split(bern(1, 2, 1), twin_index(0, 1), mc * a, twin_index(1, 0), ma * c);
  split(bern(1, 1, 2), twin_index(1, 1), ma * b, twin_index(2, 0), mb * a);
}

std::vector<BezierCurve> GregoryTriPatch::boundary_curves() const {
  std::vector<BezierCurve> c;
  for (int s = 0; s < 3; ++s) {
    std::vector<Vec3> p;
    for (int j = 0; j < 5; ++j) p.push_back(points_[boundary_index(s, j)]);
    c.emplace_back(std::move(p));
  }
  return c;
}

}  // namespace pl
