// NURBS patch with fixed weights: S = sum_ij N_i(u) N_j(v) w_ij P_ij / sum_ij N_i(u) N_j(v) w_ij.
// The rational basis phi_ij = N_i N_j w_ij / W is a Jet quotient, so S stays linear in the
// control points (incremental drags work as for every patch). Points and weights at i*nv + j.
#pragma once

#include "core/patch/spline_grid_patch.hpp"

namespace pl {

class NurbsPatch final : public SplineGridPatch<NurbsPatch> {
 public:
  static constexpr const char* kType = "nurbs";  // the scene-format type name
  // Throws std::invalid_argument for invalid knots, counts, or non-positive weights.
  NurbsPatch(int p, int q, std::vector<double> knots_u, std::vector<double> knots_v, std::size_t nu,
             std::size_t nv, std::vector<Vec3> points, std::vector<double> weights);

  // Exact sphere: u runs along a meridian half circle from the south to the north pole (5
  // points), v around the axis z (9 points). The poles are degenerate (S_v = 0) rows.
  static NurbsPatch sphere(Vec3 center, double radius);
  // Exact cylinder about the z axis: u around (9 points), v along z from z0 to z1 (linear).
  static NurbsPatch cylinder(Vec3 base_center, double radius, double height);

  void basis(Vec2 x, std::span<Jet> out) const override;
  SurfaceJet evaluate(Vec2 x) const override;
  void influence(std::size_t k, std::span<const Vec2> xs, std::span<Jet> out) const override;
  // The side's NURBS curve (spline_boundary_point), exact for any knots and weights.
  Vec3 boundary_point(int side, double t) const override;

  const std::vector<double>& weights() const { return weights_; }
  NurbsPatch inserted_u(double t) const;  // same surface, knot t inserted (homogeneous Boehm)

 private:
  std::vector<double> weights_;
};

}  // namespace pl
