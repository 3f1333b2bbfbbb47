// Tensor-product Bézier patch of degree (m, n) over [0,1]^2:
//   S(u,v) = sum_i sum_j B_i^m(u) B_j^n(v) P_ij,   P_ij = points[i*(n+1) + j].
//
//      v ^   P_0n ---- P_mn          side 0: v = 0  (P_00 .. P_m0)
//        |    |          |           side 1: u = 1  (P_m0 .. P_mn)
//        |   P_00 ---- P_m0          side 2: v = 1  (P_mn .. P_0n)
//        +--------------> u          side 3: u = 0  (P_0n .. P_00)
#pragma once

#include "core/patch/unit_square_patch.hpp"

namespace pl {

class BezierPatch final : public UnitSquarePatch<BezierPatch> {
 public:
  static constexpr const char* kType = "bezier";  // the scene-format type name
  // Throws std::invalid_argument if degrees < 1 or the point count is not (m+1)(n+1).
  BezierPatch(int m, int n, std::vector<Vec3> points);

  ControlPointKind kind(std::size_t k) const override;
  void basis(Vec2 x, std::span<Jet> out) const override;
  SurfaceJet evaluate(Vec2 x) const override;
  void influence(std::size_t k, std::span<const Vec2> xs, std::span<Jet> out) const override;
  std::vector<BezierCurve> boundary_curves() const override;

  int degree_u() const { return m_; }
  int degree_v() const { return n_; }
  const Vec3& at(int i, int j) const { return points_[i * (n_ + 1) + j]; }

 private:
  int m_, n_;
};

}  // namespace pl
