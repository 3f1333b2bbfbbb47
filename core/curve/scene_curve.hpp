// A curve of a scene: one of the classic curve types as the file states it (so that it is written
// back as it was read), its exact B-spline form for every operation, and its own evaluation.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/curve/spline_curve.hpp"

namespace pl {

enum class CurveType { Bezier, Interpolating, Hermite, BSpline, Nurbs };

std::string_view curve_type_name(CurveType t);  // "bezier", "interpolating", ...

struct SceneCurve {
  std::string name;  // may be empty; then tools call it curve<i>
  CurveType type = CurveType::Bezier;
  // bezier: P0..Pd; interpolating: p0..p3; hermite: p0, p1; bspline/nurbs: P0..Pn.
  std::vector<Vec3> points;
  std::vector<Vec3> tangents;   // hermite: d0, d1
  int degree = 0;               // bspline/nurbs (the others: see curve_degree)
  std::vector<double> knots;    // bspline/nurbs
  std::vector<double> weights;  // nurbs

  // Polynomial types: [0, 1]; spline types: [knots[p], knots[n]].
  double t_min() const;
  double t_max() const;
};

int curve_degree(const SceneCurve& c);
// The curve's name, or curve<i> for an unnamed one.
inline std::string curve_name(const SceneCurve& c, std::size_t index) {
  return c.name.empty() ? "curve" + std::to_string(index) : c.name;
}
// Throws std::invalid_argument if the data does not make a curve of its type (counts, knots,
// weights, degree).
void validate_curve(const SceneCurve& c);

// The exact B-spline (NURBS for nurbs) form, on the curve's own parameter range.
SplineCurve spline_form(const SceneCurve& c);
// A bspline (or nurbs, if rational) scene curve of a spline form.
SceneCurve curve_of_spline(const SplineCurve& s, std::string name);

// Evaluation by the type's own formula (the interpolating cubic from its matrix M_I, Hermite
// from its basis), so that the type's defining properties hold to rounding.
CurvePoint evaluate(const SceneCurve& c, double t);
// The same along a curve: `span` carries the knot span from one call to the next (start at -1),
// so that a run of evaluations in increasing t does not search the knots each time (on a spline
// of 400,000 points that search is most of the cost). Ignored by the polynomial types.
CurvePoint evaluate(const SceneCurve& c, double t, int& span);
// The spans (non-empty knot intervals in range; [0, 1] for the polynomial types).
std::vector<std::pair<double, double>> curve_spans(const SceneCurve& c);
std::size_t curve_span_count(const SceneCurve& c);  // curve_spans(c).size(), without the list
// The parameters of N + 1 uniform samples per span, span after span, each shared end once.
std::vector<double> curve_sample_parameters(const SceneCurve& c, int per_span);
// The same parameters handed to f one by one, in order, without the list: a spline of 400,000
// points has 3.2 million samples at 8 per span, and the figures taken from them need one at a time.
template <class F>
void for_each_sample_parameter(const SceneCurve& c, int per_span, F&& f) {
  bool first = true;
  auto span = [&](double a, double b) {
    for (int k = first ? 0 : 1; k <= per_span; ++k)
      f(k == per_span ? b : a + (b - a) * (double(k) / per_span));
    first = false;
  };
  if (c.type != CurveType::BSpline && c.type != CurveType::Nurbs) return span(0.0, 1.0);
  for (std::size_t s = c.degree; s < c.points.size(); ++s)
    if (c.knots[s] < c.knots[s + 1]) span(c.knots[s], c.knots[s + 1]);
}

// The editing operations; each leaves the point set of the curve unchanged (up to rounding).
// Knot insertion turns a polynomial type into a bspline; elevation keeps a Bézier a Bézier;
// split and reverse keep the type where the type allows it.
SceneCurve curve_knot_inserted(const SceneCurve& c, double t);
SceneCurve curve_degree_elevated(const SceneCurve& c);
std::pair<SceneCurve, SceneCurve> curve_split(const SceneCurve& c, double t);
SceneCurve curve_reversed(const SceneCurve& c);

}  // namespace pl
