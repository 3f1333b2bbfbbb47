#include "core/patch/gregory_quad.hpp"

#include <array>
#include <cassert>
#include <stdexcept>

#include "core/math/bernstein.hpp"
#include "core/patch/twin_weight.hpp"

namespace pl {

namespace {

// Boundary point index of grid position (i, j), or -1 for the four interior positions.
constexpr int boundary_of(int i, int j) {
  if (j == 0) return i;                   // side 0
  if (i == 3) return 3 + j;               // side 1
  if (j == 3) return 6 + (3 - i);         // side 2
  if (i == 0) return (9 + (3 - j)) % 12;  // side 3
  return -1;
}

}  // namespace

GregoryQuadPatch::GregoryQuadPatch(std::vector<Vec3> points) : PatchType(std::move(points)) {
  if (points_.size() != kPointCount)
    throw std::invalid_argument("a quadrilateral Gregory patch needs 20 points, got " +
                                std::to_string(points_.size()));
}

ControlPointKind GregoryQuadPatch::kind(std::size_t k) const {
  return k < 12 ? ControlPointKind::Boundary : ControlPointKind::Twin;
}

void GregoryQuadPatch::basis(Vec2 x, std::span<Jet> out) const {
  assert(out.size() == kPointCount);
  std::array<double, 4> u0, u1, u2, v0, v1, v2;
  bernstein_all_d2(3, x.x, u0, u1, u2);
  bernstein_all_d2(3, x.y, v0, v1, v2);
  const auto grid = [&](int i, int j) {
    return Jet(u0[i] * v0[j], u1[i] * v0[j], u0[i] * v1[j], u2[i] * v0[j], u1[i] * v1[j],
               u0[i] * v2[j]);
  };
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      if (const int b = boundary_of(i, j); b >= 0) out[b] = grid(i, j);
  const Jet u = Jet::u(x.x), v = Jet::v(x.y), mu = 1.0 - u, mv = 1.0 - v;
  // Each interior grid function is shared by its twins: weight of the twin of side X is the
  // distance to the corner's other side (see the header).
  const auto split = [&](int i, int j, std::size_t ta, const Jet& wa, std::size_t tb,
                         const Jet& wb) {
    const Jet g = grid(i, j), r = twin_weight(wa, wb);
    out[ta] = g * r;
    out[tb] = g * (1.0 - r);
  };
  split(1, 1, twin_index(0, 0), u, twin_index(3, 1), v);
  split(2, 1, twin_index(0, 1), mu, twin_index(1, 0), v);
  split(2, 2, twin_index(1, 1), mv, twin_index(2, 0), mu);
  split(1, 2, twin_index(2, 1), u, twin_index(3, 0), mv);
}

std::vector<BezierCurve> GregoryQuadPatch::boundary_curves() const {
  std::vector<BezierCurve> c;
  for (int s = 0; s < 4; ++s) {
    std::vector<Vec3> p;
    for (int j = 0; j < 4; ++j) p.push_back(points_[boundary_index(s, j)]);
    c.emplace_back(std::move(p));
  }
  return c;
}

}  // namespace pl
