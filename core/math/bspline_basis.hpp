// B-spline basis functions N_{i,p} on a knot vector (Cox-de Boor recursion) with first and
// second derivatives. Used by B-spline and NURBS curves and surfaces.
#pragma once

#include <array>
#include <span>
#include <vector>

namespace pl {

constexpr int kMaxSplineDegree = 15;

// Throws std::invalid_argument unless: 1 <= p <= 15, n >= p + 1 control points,
// knots.size() == n + p + 1, knots finite and non-decreasing, no interior knot of multiplicity
// > p, and a non-empty parameter range [knots[p], knots[n]].
void validate_knots(int p, std::span<const double> knots, std::size_t n);

// The span i (p <= i <= n-1, knots[i] < knots[i+1]) whose polynomial piece is used at t; t
// outside [knots[p], knots[n]] uses the first or last piece (its polynomial extension).
int find_span(int p, std::span<const double> knots, std::size_t n, double t);
// The same span, found in O(1) when t lies in span `hint` or in the one after it (samples and
// quadrature points along a curve mostly do); otherwise by the binary search above, which on a
// curve of 400,000 points costs 19 probes scattered over 3 MB of knots per evaluation.
int find_span(int p, std::span<const double> knots, std::size_t n, double t, int hint);

struct SplineBasis {
  int span = 0;  // functions N_{span-p} .. N_{span} are the non-zero ones
  std::array<double, kMaxSplineDegree + 1> d0{}, d1{}, d2{};  // index r is N_{span-p+r}
};

SplineBasis spline_basis(int p, std::span<const double> knots, std::size_t n, double t);
// The basis at t on a given span (one find_span returned for t).
SplineBasis spline_basis_at(int p, std::span<const double> knots, int span, double t);

}  // namespace pl
