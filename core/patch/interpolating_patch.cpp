#include "core/patch/interpolating_patch.hpp"

#include <cassert>
#include <stdexcept>

#include "core/curve/interpolating_curve.hpp"
#include "core/patch/cubic_tensor.hpp"

namespace pl {

InterpolatingPatch::InterpolatingPatch(std::vector<Vec3> points) : PatchType(std::move(points)) {
  if (points_.size() != 16)
    throw std::invalid_argument("an interpolating patch needs 16 points, got " +
                                std::to_string(points_.size()));
}

ControlPointKind InterpolatingPatch::kind(std::size_t k) const {
  const int i = static_cast<int>(k) / 4, j = static_cast<int>(k) % 4;
  return (i == 0 || i == 3 || j == 0 || j == 3) ? ControlPointKind::Boundary
                                                : ControlPointKind::Inner;
}

void InterpolatingPatch::basis(Vec2 x, std::span<Jet> out) const {
  assert(out.size() == 16);
  cubic_tensor_basis(interpolating_basis(x.x), interpolating_basis(x.y), out);
}

void InterpolatingPatch::influence(std::size_t k, std::span<const Vec2> xs,
                                   std::span<Jet> out) const {
  for (std::size_t s = 0; s < xs.size(); ++s)
    out[s] = cubic_tensor_phi(interpolating_basis(xs[s].x), interpolating_basis(xs[s].y),
                              static_cast<int>(k) / 4, static_cast<int>(k) % 4);
}

std::vector<BezierCurve> InterpolatingPatch::boundary_curves() const {
  auto p = [&](int i, int j) { return points_[i * 4 + j]; };
  // Sides run counter-clockwise (unit_square.hpp); a reversed interpolating cubic is the one
  // through the reversed points.
  return {InterpolatingCurve({p(0, 0), p(1, 0), p(2, 0), p(3, 0)}).to_bezier(),
          InterpolatingCurve({p(3, 0), p(3, 1), p(3, 2), p(3, 3)}).to_bezier(),
          InterpolatingCurve({p(3, 3), p(2, 3), p(1, 3), p(0, 3)}).to_bezier(),
          InterpolatingCurve({p(0, 3), p(0, 2), p(0, 1), p(0, 0)}).to_bezier()};
}

}  // namespace pl
