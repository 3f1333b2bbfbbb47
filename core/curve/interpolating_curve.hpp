// The interpolating cubic: through p0..p3 at t = 0, 1/3, 2/3, 1, with
// f(t) = [1 t t^2 t^3] M_I [p0 p1 p2 p3]^T.
#pragma once

#include <array>

#include "core/curve/bezier_curve.hpp"

namespace pl {

class InterpolatingCurve {
 public:
  explicit InterpolatingCurve(const std::array<Vec3, 4>& points) : points_(points) {}

  const std::array<Vec3, 4>& points() const { return points_; }
  CurvePoint evaluate(double t) const;
  double curvature(double t) const;
  BezierCurve to_bezier() const;  // the same cubic in Bézier form (exact)

 private:
  std::array<Vec3, 4> points_;
};

// Bézier points of the cubic with monomial coefficients c0..c3 (shared by the cubic types).
BezierCurve bezier_from_monomials(const std::array<Vec3, 4>& c);

}  // namespace pl
