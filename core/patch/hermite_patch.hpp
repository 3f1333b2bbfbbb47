// Bicubic Hermite (Ferguson) patch: r(u,v) = F(u) Q F(v)^T with
// F = [alpha0 alpha1 beta0 beta1] and the 4x4 matrix of corner data (points[a*4+b] = Q_ab):
//   Q = | r(0,0)   r(0,1)   r_v(0,0)  r_v(0,1)  |
//       | r(1,0)   r(1,1)   r_v(1,0)  r_v(1,1)  |
//       | r_u(0,0) r_u(0,1) r_uv(0,0) r_uv(0,1) |
//       | r_u(1,0) r_u(1,1) r_uv(1,0) r_uv(1,1) |
// Derivative "control points" are vectors; the surface is still linear in all 16 entries.
#pragma once

#include "core/domain/unit_square.hpp"
#include "core/patch/patch.hpp"

namespace pl {

class HermitePatch final : public PatchType<HermitePatch> {
 public:
  static constexpr const char* kType = "hermite";  // the scene-format type name
  explicit HermitePatch(std::vector<Vec3> q);      // exactly 16 entries, order above

  const Domain& domain() const override { return domain_; }
  ControlPointKind kind(std::size_t k) const override;
  void basis(Vec2 x, std::span<Jet> out) const override;
  void influence(std::size_t k, std::span<const Vec2> xs, std::span<Jet> out) const override;
  std::vector<BezierCurve> boundary_curves() const override;

  const Vec3& r(int i, int j) const { return points_[i * 4 + j]; }
  const Vec3& ru(int i, int j) const { return points_[(2 + i) * 4 + j]; }
  const Vec3& rv(int i, int j) const { return points_[i * 4 + 2 + j]; }
  const Vec3& ruv(int i, int j) const { return points_[(2 + i) * 4 + 2 + j]; }

 private:
  UnitSquareDomain domain_;
};

}  // namespace pl
