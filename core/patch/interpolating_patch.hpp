// Bicubic interpolating surface: through a 4x4 grid of points p_ij at
// (u, v) = (i/3, j/3), f(u,v) = [1 u u^2 u^3] M_I P M_I^T [1 v v^2 v^3]^T, p_ij = points[i*4+j].
#pragma once

#include "core/domain/unit_square.hpp"
#include "core/patch/patch.hpp"

namespace pl {

class InterpolatingPatch final : public PatchType<InterpolatingPatch> {
 public:
  static constexpr const char* kType = "interpolating";   // the scene-format type name
  explicit InterpolatingPatch(std::vector<Vec3> points);  // exactly 16 points

  const Domain& domain() const override { return domain_; }
  ControlPointKind kind(std::size_t k) const override;
  void basis(Vec2 x, std::span<Jet> out) const override;
  void influence(std::size_t k, std::span<const Vec2> xs, std::span<Jet> out) const override;
  std::vector<BezierCurve> boundary_curves() const override;

 private:
  UnitSquareDomain domain_;
};

}  // namespace pl
