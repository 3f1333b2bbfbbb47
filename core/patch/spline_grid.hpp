// The tensor-product B-spline basis shared by B-spline and NURBS patches: degrees (p, q), knot
// vectors, nu x nv control points (index i*nv + j, i along u). The patch domain [0,1]^2 is
// mapped linearly onto [u_min, u_max] x [v_min, v_max] of the knots; derivatives include that
// scale, so every patch type sees one unit square.
#pragma once

#include <array>
#include <vector>

#include "core/curve/bezier_curve.hpp"
#include "core/math/bspline_basis.hpp"
#include "core/math/jet.hpp"
#include "core/math/vec.hpp"
#include "core/patch/surface_jet.hpp"

namespace pl {

class SplineGrid {
 public:
  // Throws std::invalid_argument for invalid knots (validate_knots) in either direction.
  SplineGrid(int p, int q, std::vector<double> knots_u, std::vector<double> knots_v, std::size_t nu,
             std::size_t nv);

  int p() const { return p_; }
  int q() const { return q_; }
  std::size_t nu() const { return nu_; }
  std::size_t nv() const { return nv_; }
  const std::vector<double>& knots_u() const { return ku_; }
  const std::vector<double>& knots_v() const { return kv_; }
  double u_of(double x) const { return ku_[p_] + x * (ku_[nu_] - ku_[p_]); }
  double v_of(double y) const { return kv_[q_] + y * (kv_[nv_] - kv_[q_]); }

  // The (p+1)(q+1) polynomial basis functions non-zero at x: N_{i0+a}(u) N_{j0+b}(v) at
  // phi[a*(q+1)+b] (a Jet in the domain coordinates).
  struct Local {
    int i0 = 0, j0 = 0;
    std::array<Jet, (kMaxSplineDegree + 1) * (kMaxSplineDegree + 1)> phi;
  };
  Local local(Vec2 x) const;
  // S and its derivatives from a local basis (polynomial or rational) and the control points.
  SurfaceJet combine(const Local& l, const std::vector<Vec3>& points) const;
  // Whether control point (i, j) can be non-zero at x (its span contains x's span).
  bool touches(std::size_t k, Vec2 x) const;

 private:
  int p_, q_;
  std::vector<double> ku_, kv_;
  std::size_t nu_, nv_;
};

}  // namespace pl
