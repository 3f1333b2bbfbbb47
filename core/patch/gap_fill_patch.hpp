// G1 gap filling between two B-spline patches: q over [c,d] x [a,b] and r over
// [e,f] x [a,b] (same v range, v knots may differ). The fill s over [0,1] x [a,b] is cubic
// Hermite in u between the curves q(d, v) and r(e, v) with cross-boundary derivatives rescaled
// to the gap width d(v) = |q(d,v) - r(e,v)|:
//   s_u(0, v) = c1(v) q_u(d, v),  c1 = d / |q_u(d, v)|;   s_u(1, v) = g1(v) r_u(e, v),  g1 = d /
//   |r_u(e, v)|.
// s_u is parallel to the neighbour's cross derivative (positive factor) along the whole curve, so
// q, s, r form a G1 surface. c1 and g1 are transcendental (square roots); they are evaluated
// exactly with jets and frozen with the patch (like NURBS weights), so s stays linear in the
// control points: a drag keeps G1 (s_u stays parallel to q_u), only |s_u| = d is then approximate.
//
// One Patch over [0,1]^2: u in [0,1/3] is q, [1/3,2/3] the fill, [2/3,1] r; v over [a,b].
// Control points: q's (index i*nv_q + j) then r's. q must be clamped at u = d, r at u = e.
#pragma once

#include <memory>

#include "core/curve/bspline_curve.hpp"
#include "core/domain/unit_square.hpp"
#include "core/patch/bspline_patch.hpp"
#include "core/patch/patch.hpp"

namespace pl {

class GapFillPatch final : public PatchType<GapFillPatch> {
 public:
  static constexpr const char* kType = "gap-fill";  // the scene-format type name
  // Throws std::invalid_argument if the v ranges differ, an end is not clamped, or the gap
  // width or a cross derivative vanishes somewhere along the curves.
  GapFillPatch(BSplinePatch q, BSplinePatch r);

  const Domain& domain() const override { return domain_; }
  ControlPointKind kind(std::size_t k) const override;
  void set_control_point(std::size_t k, const Vec3& p) override;
  void basis(Vec2 x, std::span<Jet> out) const override;
  // Sides 1 and 3 are r's and q's outer sides; sides 0 and 2 cross three pieces and are returned
  // as the Bézier curve on their four break points (the interface has no piecewise curve).
  std::vector<BezierCurve> boundary_curves() const override;
  // Every side exactly from the defining curves: q's and r's own sides (B-spline curves) and,
  // on the fill's stretch of sides 0 and 2, the cubic Hermite curve between q(d, v) and r(e, v)
  // with the scaled cross derivatives, built from curves of the current points.
  Vec3 boundary_point(int side, double t) const override;

  const BSplinePatch& q() const { return *q_; }
  const BSplinePatch& r() const { return *r_; }
  // Piece 0: q, 1: fill, 2: r, at its own local (u, v) in [0,1]^2 (derivatives in local u).
  SurfaceJet piece_jet(int piece, Vec2 local) const;
  // The frozen gap width d(v), for tests and display; y in [0,1].
  double gap_width(double y) const;

 private:
  void fill_basis(Vec2 local, std::span<Jet> out) const;  // over all control points

  std::shared_ptr<BSplinePatch> q_, r_;
  // Frozen boundary data of the scale functions: q(d, v), q_u(d, v), r(e, v), r_u(e, v).
  std::shared_ptr<BSplineCurve> q_end_, q_cross_, r_end_, r_cross_;
  double kq_ = 0, kr_ = 0;  // q_u = kq (P_{n-1} - P_{n-2}) at the clamped end; r_u = kr (P_1 - P_0)
  UnitSquareDomain domain_;
};

}  // namespace pl
