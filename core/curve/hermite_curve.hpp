// Cubic Hermite curve: end points p0, p1 and end derivatives d0, d1,
// f(t) = alpha0 p0 + alpha1 p1 + beta0 d0 + beta1 d1.
#pragma once

#include "core/curve/bezier_curve.hpp"

namespace pl {

class HermiteCurve {
 public:
  HermiteCurve(Vec3 p0, Vec3 p1, Vec3 d0, Vec3 d1) : p0_(p0), p1_(p1), d0_(d0), d1_(d1) {}

  CurvePoint evaluate(double t) const;
  double curvature(double t) const;
  // Exact Bézier form: p0, p0 + d0/3, p1 - d1/3, p1.
  BezierCurve to_bezier() const {
    return BezierCurve({p0_, p0_ + d0_ / 3.0, p1_ - d1_ / 3.0, p1_});
  }

 private:
  Vec3 p0_, p1_, d0_, d1_;
};

}  // namespace pl
