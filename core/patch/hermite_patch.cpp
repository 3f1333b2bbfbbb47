#include "core/patch/hermite_patch.hpp"

#include <cassert>
#include <stdexcept>

#include "core/curve/hermite_curve.hpp"
#include "core/patch/cubic_tensor.hpp"

namespace pl {

HermitePatch::HermitePatch(std::vector<Vec3> q) : PatchType(std::move(q)) {
  if (points_.size() != 16)
    throw std::invalid_argument(
        "a Hermite patch needs 16 corner vectors (r, r_u, r_v, r_uv at 4 corners), got " +
        std::to_string(points_.size()));
}

ControlPointKind HermitePatch::kind(std::size_t k) const {
  // Corner positions are on the boundary; derivative vectors are handles.
  return (k / 4 < 2 && k % 4 < 2) ? ControlPointKind::Boundary : ControlPointKind::Inner;
}

void HermitePatch::basis(Vec2 x, std::span<Jet> out) const {
  assert(out.size() == 16);
  cubic_tensor_basis(hermite_basis(x.x), hermite_basis(x.y), out);
}

void HermitePatch::influence(std::size_t k, std::span<const Vec2> xs, std::span<Jet> out) const {
  for (std::size_t s = 0; s < xs.size(); ++s)
    out[s] = cubic_tensor_phi(hermite_basis(xs[s].x), hermite_basis(xs[s].y),
                              static_cast<int>(k) / 4, static_cast<int>(k) % 4);
}

std::vector<BezierCurve> HermitePatch::boundary_curves() const {
  // Counter-clockwise sides; a side traversed backwards negates its end derivatives.
  return {HermiteCurve(r(0, 0), r(1, 0), ru(0, 0), ru(1, 0)).to_bezier(),
          HermiteCurve(r(1, 0), r(1, 1), rv(1, 0), rv(1, 1)).to_bezier(),
          HermiteCurve(r(1, 1), r(0, 1), -ru(1, 1), -ru(0, 1)).to_bezier(),
          HermiteCurve(r(0, 1), r(0, 0), -rv(0, 1), -rv(0, 0)).to_bezier()};
}

}  // namespace pl
