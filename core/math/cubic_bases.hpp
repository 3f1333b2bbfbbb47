// The cubic blending functions of the classic curve types, with first and second derivatives:
// the interpolating basis b(t) = M_I^T [1 t t^2 t^3]^T (through 4 points at t = 0, 1/3, 2/3, 1)
// and the Hermite basis [alpha0 alpha1 beta0 beta1] (J. Ferguson, "Multivariable curve
// interpolation", J. ACM 11(2), 1964).
#pragma once

#include <array>

namespace pl {

struct CubicBasis {
  std::array<double, 4> d0, d1, d2;  // values, first and second derivatives of the 4 functions
};

// Rows are the monomial coefficients c0..c3 of the curve: c = M_I p (docs/classic-types.md).
extern const double kInterpolatingMatrix[4][4];

CubicBasis interpolating_basis(double t);
// alpha0 = 2t^3 - 3t^2 + 1, alpha1 = 3t^2 - 2t^3, beta0 = t^3 - 2t^2 + t, beta1 = t^3 - t^2.
CubicBasis hermite_basis(double t);

}  // namespace pl
