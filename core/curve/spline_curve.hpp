// A B-spline or NURBS curve in one form for every operation of the editor and the exports:
// degree p, knots, control points and (for a rational curve) positive weights. The curve is
// C(t) = sum N_{i,p}(t) w_i P_i / sum N_{i,p}(t) w_i over [knots[p], knots[n]] (n points; all
// w_i = 1 when `weights` is empty). Unlike BSplineCurve this accepts every knot vector of the
// scene format, including an interior knot of multiplicity p + 1 (a curve broken in two there).
// The operations are exact: knot insertion (Boehm) and the others map the homogeneous points
// w_i P_i linearly, so the curve is unchanged up to rounding.
#pragma once

#include <glm/vec4.hpp>
#include <span>
#include <utility>
#include <vector>

#include "core/curve/bezier_curve.hpp"

namespace pl {

struct SplineCurve {
  int degree = 1;
  std::vector<double> knots;
  std::vector<Vec3> points;
  std::vector<double> weights;  // empty: polynomial

  bool rational() const { return !weights.empty(); }
  double t_min() const { return knots[degree]; }
  double t_max() const { return knots[points.size()]; }
  double weight(std::size_t i) const { return weights.empty() ? 1.0 : weights[i]; }
};

// Throws std::invalid_argument unless: 1 <= degree <= kMaxSplineDegree, points >= degree + 1,
// knots = points + degree + 1, knots finite and non-decreasing, no knot value more than
// degree + 1 times, a non-empty range, weights empty or one positive finite weight per point.
void validate_spline_curve(const SplineCurve& c);

// The non-empty knot intervals inside [t_min, t_max], in order.
std::vector<std::pair<double, double>> spline_spans(const SplineCurve& c);

// Position and first and second derivative in t. At a knot the piece on its right is used (at
// t_max the last piece).
CurvePoint evaluate(const SplineCurve& c, double t);
// The same on arrays held elsewhere (weights empty: polynomial).
CurvePoint evaluate_spline(int degree, std::span<const double> knots, std::span<const Vec3> points,
                           std::span<const double> weights, double t);
// The same, trying knot span `span` (one an earlier call left, or -1) and the next one before
// searching the knots; `span` is left at the span used. Evaluations in increasing t, as samples
// and quadrature points along a curve are made, then cost the same on any number of points.
CurvePoint evaluate_spline(int degree, std::span<const double> knots, std::span<const Vec3> points,
                           std::span<const double> weights, double t, int& span);

// t inserted once (t_min < t < t_max, multiplicity stays <= degree + 1).
SplineCurve knot_inserted(const SplineCurve& c, double t);
// Degree + 1 with every break keeping its continuity. Throws for a curve broken at an interior
// knot of multiplicity degree + 1, or at kMaxSplineDegree.
SplineCurve degree_elevated(const SplineCurve& c);
// The two pieces over [t_min, t] and [t, t_max] (t strictly inside), parameters kept.
std::pair<SplineCurve, SplineCurve> split_at(const SplineCurve& c, double t);
// The same point set run backwards: R(t_min + t_max - t) = C(t).
SplineCurve reversed(const SplineCurve& c);
// The same curve with end knots of multiplicity degree + 1 (no knot outside [t_min, t_max]).
SplineCurve clamped(const SplineCurve& c);

}  // namespace pl
