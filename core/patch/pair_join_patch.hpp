// A G1 or G2 pair of polynomial patches joined along a common boundary (the classic
// construction of pairs of patches from junction functions; docs/classic-types.md). An auxiliary
// Bézier patch p(s, t) of degree (d, m) gives the common curve p(s, 0) and, along it, the tangent
// plane (G1) and the normal curvatures (G2). Each final patch p* is of degree 5 in u (the edge
// direction, u = s) and `order` in v, with p*(u, 0) = p(u, 0) degree-elevated and, with its own
// polynomial junction functions b1, c1 (b2, c2),
//   p*_v  = b1 p_s + c1 p_t,
//   p*_vv = b2 p_s + c2 p_t + b1^2 p_ss + 2 b1 c1 p_st + c1^2 p_tt          (order 2),
// i.e. the derivatives of p(s(u,v), t(u,v)) for a reparameterisation with s_v = b1, t_v = c1,
// s_vv = b2, t_vv = c2: both patches share the auxiliary patch's tangent plane (and its second
// fundamental form), so they join G1 (G2). c1 of patch A must be positive and of patch B negative
// on [0,1] (B lies on the other side of the curve). Every product must have degree <= 5.
//
// The pair is one Patch over [0,1]^2: v in [1/2, 1] is A(u, 2v - 1), v in [0, 1/2] is B(u, 1 - 2v),
// so the normal is continuous across the junction v = 1/2. Its control points are the auxiliary
// patch's (points[i*(m+1) + j]); the final Bézier points are a fixed linear map of them, so
// dragging an auxiliary point keeps the join G1/G2.
#pragma once

#include <array>

#include "core/domain/unit_square.hpp"
#include "core/patch/bezier_patch.hpp"
#include "core/patch/patch.hpp"

namespace pl {

struct JunctionFunctions {  // Bernstein coefficients on [0,1]
  std::vector<double> b1, c1, b2, c2;
};

class PairJoinPatch final : public PatchType<PairJoinPatch> {
 public:
  static constexpr const char* kType = "pair-join";  // the scene-format type name
  // order 1 (G1) or 2 (G2). Throws std::invalid_argument for inconsistent data.
  PairJoinPatch(int order, int aux_degree_u, int aux_degree_v, std::vector<Vec3> aux_points,
                JunctionFunctions a, JunctionFunctions b);

  const Domain& domain() const override { return domain_; }
  ControlPointKind kind(std::size_t k) const override;
  void set_control_point(std::size_t k, const Vec3& p) override;
  void basis(Vec2 x, std::span<Jet> out) const override;
  SurfaceJet evaluate(Vec2 x) const override;
  // Sides 0 and 2 are exact (B's and A's far rows); sides 1 and 3 are two pieces and are returned
  // as the Bézier curve on their three end points (the interface has no piecewise curve).
  std::vector<BezierCurve> boundary_curves() const override;
  // Every side exactly: sides 1 and 3 are B's and A's end columns (Bézier curves of degree
  // `order`) joined at the junction v = 1/2.
  Vec3 boundary_point(int side, double t) const override;

  int order() const { return order_; }
  int aux_degree_u() const { return du_; }
  int aux_degree_v() const { return dv_; }
  const JunctionFunctions& junction(int which) const { return junction_[which]; }
  const BezierPatch& final_patch(int which) const { return *final_[which]; }  // 0: A, 1: B
  BezierPatch auxiliary() const { return BezierPatch(du_, dv_, points_); }

 private:
  std::vector<Vec3> construct(const std::vector<Vec3>& aux, int which) const;
  void rebuild();

  int order_, du_, dv_;
  std::array<JunctionFunctions, 2> junction_;
  // map_[w][l * size() + k]: weight of auxiliary point k in final point l of patch w.
  std::array<std::vector<double>, 2> map_;
  std::array<std::shared_ptr<BezierPatch>, 2> final_;
  UnitSquareDomain domain_;
};

}  // namespace pl
