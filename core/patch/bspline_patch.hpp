// Tensor-product B-spline patch of any degrees (p, q) and knot vectors:
//   S = sum_ij N_{i,p}(u) N_{j,q}(v) P_ij,  P_ij = points[i*nv + j],
// over [0,1]^2 mapped onto the knot ranges (spline_grid.hpp). influence() computes a control
// point's column only where its support is, so drags touch (p+1)(q+1) spans of samples.
#pragma once

#include "core/patch/spline_grid_patch.hpp"

namespace pl {

class BSplinePatch final : public SplineGridPatch<BSplinePatch> {
 public:
  static constexpr const char* kType = "bspline";  // the scene-format type name
  // Throws std::invalid_argument for invalid knots or points.size() != nu * nv.
  BSplinePatch(int p, int q, std::vector<double> knots_u, std::vector<double> knots_v,
               std::size_t nu, std::size_t nv, std::vector<Vec3> points);

  void basis(Vec2 x, std::span<Jet> out) const override;
  SurfaceJet evaluate(Vec2 x) const override;
  void influence(std::size_t k, std::span<const Vec2> xs, std::span<Jet> out) const override;
  // The side's B-spline curve (spline_boundary_point), exact for any knots.
  Vec3 boundary_point(int side, double t) const override;

  // The same surface with knot t (in the knot range, not the domain) inserted in u or v.
  BSplinePatch inserted_u(double t) const;
  BSplinePatch inserted_v(double t) const;
};

// The point at side parameter t of side `side` of a B-spline (weights empty) or NURBS grid,
// through the curve classes (BSplineCurve, NurbsCurve), independently of SplineGrid::local():
// the cross-direction curves of the homogeneous points at the side's fixed knot value give the
// side's own (rational) B-spline control points, whose curve is then evaluated along the side.
// Exact for any number of spans, clamped or not.
Vec3 spline_boundary_point(const SplineGrid& g, const std::vector<Vec3>& points,
                           const std::vector<double>& weights, int side, double t);

}  // namespace pl
