// Bézier curves of any degree in 3D: evaluation with derivatives, de Casteljau subdivision,
// degree elevation. Network edges are the cubic case.
#pragma once

#include <vector>

#include "core/math/vec.hpp"

namespace pl {

struct CurvePoint {
  Vec3 p, d1, d2;  // position, first and second derivative in t
};

class BezierCurve {
 public:
  explicit BezierCurve(std::vector<Vec3> control_points);  // at least one point

  int degree() const { return static_cast<int>(cp_.size()) - 1; }
  const std::vector<Vec3>& control_points() const { return cp_; }

  Vec3 point(double t) const;  // de Casteljau
  CurvePoint evaluate(double t) const;
  BezierCurve elevated() const;  // same curve, degree + 1
  BezierCurve elevated_to(int degree) const;
  // The two halves at t: [0,t] and [t,1], each reparameterised to [0,1].
  std::pair<BezierCurve, BezierCurve> split(double t) const;
  BezierCurve reversed() const;
  BezierCurve derivative() const;  // hodograph, degree - 1 (degree 0 gives the zero curve)

 private:
  std::vector<Vec3> cp_;
};

}  // namespace pl
