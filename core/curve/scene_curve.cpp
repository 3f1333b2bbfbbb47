#include "core/curve/scene_curve.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>

#include "core/curve/hermite_curve.hpp"
#include "core/curve/interpolating_curve.hpp"
#include "core/math/bernstein.hpp"
#include "core/math/bspline_basis.hpp"

namespace pl {

namespace {

bool is_spline(CurveType t) {
  return t == CurveType::BSpline || t == CurveType::Nurbs;
}

BezierCurve bezier_form(const SceneCurve& c) {
  switch (c.type) {
    case CurveType::Interpolating:
      return InterpolatingCurve({c.points[0], c.points[1], c.points[2], c.points[3]}).to_bezier();
    case CurveType::Hermite:
      return HermiteCurve(c.points[0], c.points[1], c.tangents[0], c.tangents[1]).to_bezier();
    default:
      return BezierCurve(c.points);
  }
}

SceneCurve bezier_curve(std::vector<Vec3> points, std::string name) {
  SceneCurve r;
  r.name = std::move(name);
  r.type = CurveType::Bezier;
  r.points = std::move(points);
  return r;
}

void expect_count(const char* what, std::size_t got, std::size_t want) {
  if (got != want)
    throw std::invalid_argument("expected " + std::to_string(want) + " " + what + ", got " +
                                std::to_string(got));
}

}  // namespace

std::string_view curve_type_name(CurveType t) {
  switch (t) {
    case CurveType::Bezier:
      return "bezier";
    case CurveType::Interpolating:
      return "interpolating";
    case CurveType::Hermite:
      return "hermite";
    case CurveType::BSpline:
      return "bspline";
    case CurveType::Nurbs:
      return "nurbs";
  }
  return "";
}

double SceneCurve::t_min() const {
  return is_spline(type) ? knots[degree] : 0.0;
}

double SceneCurve::t_max() const {
  return is_spline(type) ? knots[points.size()] : 1.0;
}

int curve_degree(const SceneCurve& c) {
  switch (c.type) {
    case CurveType::Bezier:
      return static_cast<int>(c.points.size()) - 1;
    case CurveType::Interpolating:
    case CurveType::Hermite:
      return 3;
    default:
      return c.degree;
  }
}

void validate_curve(const SceneCurve& c) {
  switch (c.type) {
    case CurveType::Bezier:
      if (c.points.size() < 2)
        throw std::invalid_argument("a Bézier curve needs at least 2 points (degree >= 1), got " +
                                    std::to_string(c.points.size()));
      if (c.points.size() > std::size_t(kMaxSplineDegree) + 1)
        throw std::invalid_argument("a Bézier curve has at most " +
                                    std::to_string(kMaxSplineDegree + 1) + " points");
      break;
    case CurveType::Interpolating:
      expect_count("points", c.points.size(), 4);
      break;
    case CurveType::Hermite:
      expect_count("points", c.points.size(), 2);
      expect_count("tangents", c.tangents.size(), 2);
      break;
    case CurveType::BSpline:
    case CurveType::Nurbs:
      validate_spline_curve(spline_form(c));
      break;
  }
}

SplineCurve spline_form(const SceneCurve& c) {
  SplineCurve s;
  if (is_spline(c.type)) {
    s.degree = c.degree;
    s.knots = c.knots;
    s.points = c.points;
    if (c.type == CurveType::Nurbs) s.weights = c.weights;
    return s;
  }
  s.points = bezier_form(c).control_points();
  s.degree = static_cast<int>(s.points.size()) - 1;
  s.knots.assign(s.degree + 1, 0.0);
  s.knots.insert(s.knots.end(), s.degree + 1, 1.0);
  return s;
}

SceneCurve curve_of_spline(const SplineCurve& s, std::string name) {
  SceneCurve c;
  c.name = std::move(name);
  c.type = s.rational() ? CurveType::Nurbs : CurveType::BSpline;
  c.degree = s.degree;
  c.knots = s.knots;
  c.points = s.points;
  c.weights = s.weights;
  return c;
}

CurvePoint evaluate(const SceneCurve& c, double t) {
  int span = -1;
  return evaluate(c, t, span);
}

CurvePoint evaluate(const SceneCurve& c, double t, int& span) {
  switch (c.type) {
    case CurveType::Bezier: {
      // BezierCurve::evaluate's sums, on the scene's points and stack arrays: a curve evaluated
      // at many samples allocates nothing.
      const int n = static_cast<int>(c.points.size()) - 1;
      std::array<double, kMaxSplineDegree + 1> d0, d1, d2;
      bernstein_all_d2(n, t, std::span(d0.data(), n + 1), std::span(d1.data(), n + 1),
                       std::span(d2.data(), n + 1));
      CurvePoint r{Vec3(0), Vec3(0), Vec3(0)};
      for (int i = 0; i <= n; ++i) {
        r.p += d0[i] * c.points[i];
        r.d1 += d1[i] * c.points[i];
        r.d2 += d2[i] * c.points[i];
      }
      return r;
    }
    case CurveType::Interpolating:
      return InterpolatingCurve({c.points[0], c.points[1], c.points[2], c.points[3]}).evaluate(t);
    case CurveType::Hermite:
      return HermiteCurve(c.points[0], c.points[1], c.tangents[0], c.tangents[1]).evaluate(t);
    default:
      return evaluate_spline(c.degree, c.knots, c.points,
                             c.type == CurveType::Nurbs ? std::span<const double>(c.weights)
                                                        : std::span<const double>(),
                             t, span);
  }
}

std::vector<std::pair<double, double>> curve_spans(const SceneCurve& c) {
  if (!is_spline(c.type)) return {{0.0, 1.0}};
  std::vector<std::pair<double, double>> spans;
  for (std::size_t s = c.degree; s < c.points.size(); ++s)
    if (c.knots[s] < c.knots[s + 1]) spans.emplace_back(c.knots[s], c.knots[s + 1]);
  return spans;
}

std::size_t curve_span_count(const SceneCurve& c) {
  if (!is_spline(c.type)) return 1;
  std::size_t n = 0;
  for (std::size_t s = c.degree; s < c.points.size(); ++s) n += c.knots[s] < c.knots[s + 1];
  return n;
}

std::vector<double> curve_sample_parameters(const SceneCurve& c, int per_span) {
  std::vector<double> ts;
  ts.reserve(curve_span_count(c) * per_span + 1);
  for_each_sample_parameter(c, per_span, [&](double t) { ts.push_back(t); });
  return ts;
}

SceneCurve curve_knot_inserted(const SceneCurve& c, double t) {
  return curve_of_spline(knot_inserted(spline_form(c), t), c.name);
}

SceneCurve curve_degree_elevated(const SceneCurve& c) {
  if (is_spline(c.type)) return curve_of_spline(degree_elevated(spline_form(c)), c.name);
  if (curve_degree(c) >= kMaxSplineDegree)
    throw std::invalid_argument("the degree is already " + std::to_string(kMaxSplineDegree));
  return bezier_curve(bezier_form(c).elevated().control_points(), c.name);
}

std::pair<SceneCurve, SceneCurve> curve_split(const SceneCurve& c, double t) {
  if (is_spline(c.type)) {
    auto [l, r] = split_at(spline_form(c), t);
    return {curve_of_spline(l, c.name), curve_of_spline(r, c.name.empty() ? "" : c.name + "'")};
  }
  if (!(t > 0 && t < 1)) throw std::invalid_argument("a curve is split strictly inside (0, 1)");
  auto [l, r] = bezier_form(c).split(t);
  return {bezier_curve(l.control_points(), c.name),
          bezier_curve(r.control_points(), c.name.empty() ? "" : c.name + "'")};
}

SceneCurve curve_reversed(const SceneCurve& c) {
  SceneCurve r = c;
  switch (c.type) {
    case CurveType::Bezier:
    case CurveType::Interpolating:
      std::reverse(r.points.begin(), r.points.end());
      break;
    case CurveType::Hermite:
      r.points = {c.points[1], c.points[0]};
      r.tangents = {-c.tangents[1], -c.tangents[0]};
      break;
    default: {
      const SplineCurve s = reversed(spline_form(c));
      r.knots = s.knots;
      r.points = s.points;
      r.weights = s.weights;
    }
  }
  return r;
}

}  // namespace pl
