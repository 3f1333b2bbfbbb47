#include "core/curve/interpolating_curve.hpp"

#include "core/curve/curvature.hpp"
#include "core/math/cubic_bases.hpp"

namespace pl {

CurvePoint InterpolatingCurve::evaluate(double t) const {
  const CubicBasis b = interpolating_basis(t);
  CurvePoint c{Vec3(0), Vec3(0), Vec3(0)};
  for (int k = 0; k < 4; ++k) {
    c.p += b.d0[k] * points_[k];
    c.d1 += b.d1[k] * points_[k];
    c.d2 += b.d2[k] * points_[k];
  }
  return c;
}

double InterpolatingCurve::curvature(double t) const {
  return curve_curvature(evaluate(t));
}

BezierCurve bezier_from_monomials(const std::array<Vec3, 4>& c) {
  return BezierCurve(
      {c[0], c[0] + c[1] / 3.0, c[0] + 2.0 * c[1] / 3.0 + c[2] / 3.0, c[0] + c[1] + c[2] + c[3]});
}

BezierCurve InterpolatingCurve::to_bezier() const {
  std::array<Vec3, 4> c{Vec3(0), Vec3(0), Vec3(0), Vec3(0)};
  for (int r = 0; r < 4; ++r)
    for (int k = 0; k < 4; ++k) c[r] += kInterpolatingMatrix[r][k] * points_[k];
  return bezier_from_monomials(c);
}

}  // namespace pl
