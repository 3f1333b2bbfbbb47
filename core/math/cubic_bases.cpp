#include "core/math/cubic_bases.hpp"

namespace pl {

// Solving p_k = f(k/3), k = 0..3, for the monomial coefficients (the matrix M_I of the
// interpolating cubic, docs/classic-types.md).
const double kInterpolatingMatrix[4][4] = {
    {1, 0, 0, 0}, {-5.5, 9, -4.5, 1}, {9, -22.5, 18, -4.5}, {-4.5, 13.5, -13.5, 4.5}};

namespace {
// Basis from a monomial coefficient matrix: b_k(t) = sum_r M[r][k] t^r.
CubicBasis from_monomials(const double m[4][4], double t) {
  const double mono[3][4] = {{1, t, t * t, t * t * t}, {0, 1, 2 * t, 3 * t * t}, {0, 0, 2, 6 * t}};
  CubicBasis b{};
  for (int k = 0; k < 4; ++k)
    for (int r = 0; r < 4; ++r) {
      b.d0[k] += m[r][k] * mono[0][r];
      b.d1[k] += m[r][k] * mono[1][r];
      b.d2[k] += m[r][k] * mono[2][r];
    }
  return b;
}
const double kHermiteMatrix[4][4] = {{1, 0, 0, 0}, {0, 0, 1, 0}, {-3, 3, -2, -1}, {2, -2, 1, 1}};
}  // namespace

CubicBasis interpolating_basis(double t) {
  return from_monomials(kInterpolatingMatrix, t);
}
CubicBasis hermite_basis(double t) {
  return from_monomials(kHermiteMatrix, t);
}

}  // namespace pl
