#include "core/curve/hermite_curve.hpp"

#include "core/curve/curvature.hpp"
#include "core/math/cubic_bases.hpp"

namespace pl {

CurvePoint HermiteCurve::evaluate(double t) const {
  const CubicBasis b = hermite_basis(t);
  const Vec3 data[4] = {p0_, p1_, d0_, d1_};
  CurvePoint c{Vec3(0), Vec3(0), Vec3(0)};
  for (int k = 0; k < 4; ++k) {
    c.p += b.d0[k] * data[k];
    c.d1 += b.d1[k] * data[k];
    c.d2 += b.d2[k] * data[k];
  }
  return c;
}

double HermiteCurve::curvature(double t) const {
  return curve_curvature(evaluate(t));
}

}  // namespace pl
