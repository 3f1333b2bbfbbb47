#include "core/curve/cubic_fit.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace pl {

namespace {

// The curve on [a, b] alone: evaluated at its own t_min and t_max, it gives the one-sided values
// of the whole curve at a and b (the piece right of a, the piece left of b).
SplineCurve piece(const SplineCurve& c, double a, double b) {
  SplineCurve s = c;
  if (a > s.t_min()) s = split_at(s, a).second;
  if (b < s.t_max()) s = split_at(s, b).first;
  return s;
}

std::array<Vec3, 4> hermite_span(const SplineCurve& s) {
  const double h = s.t_max() - s.t_min();
  const CurvePoint p0 = evaluate(s, s.t_min()), p1 = evaluate(s, s.t_max());
  return {p0.p, p0.p + p0.d1 * (h / 3), p1.p - p1.d1 * (h / 3), p1.p};
}

Vec3 bezier_point(const std::array<Vec3, 4>& b, double u) {
  const double v = 1 - u;
  return v * v * v * b[0] + 3 * v * v * u * b[1] + 3 * v * u * u * b[2] + u * u * u * b[3];
}

// At kFitChecks points of every knot span inside the piece, so that no span of the curve goes
// unchecked however many a cubic covers.
double span_deviation(const SplineCurve& s, const std::array<Vec3, 4>& b) {
  const double a = s.t_min(), h = s.t_max() - s.t_min();
  double worst = 0;
  int span = -1;
  for (const auto& [t0, t1] : spline_spans(s))
    for (int k = 0; k <= kFitChecks; ++k) {
      const double t = k == kFitChecks ? t1 : t0 + (t1 - t0) * (double(k) / kFitChecks);
      const Vec3 p = evaluate_spline(s.degree, s.knots, s.points, s.weights, t, span).p;
      worst = std::max(worst, glm::length(p - bezier_point(b, (t - a) / h)));
    }
  return worst;
}

// Where [a, b] is cut: the curve's knot nearest the middle strictly inside, else the middle.
double cut(const SplineCurve& c, double a, double b) {
  const double mid = 0.5 * (a + b);
  double best = mid, distance = INFINITY;
  for (double k : c.knots)
    if (k > a && k < b && std::fabs(k - mid) < distance) best = k, distance = std::fabs(k - mid);
  return best;
}

}  // namespace

CubicChain cubic_chain(const SceneCurve& curve, double tolerance, int max_spans) {
  if (!(tolerance > 0) || !std::isfinite(tolerance))
    throw std::invalid_argument("the fitting tolerance must be a positive number");
  const SplineCurve c = spline_form(curve);
  CubicChain chain;
  // Depth first, left to right: the spans come out in order.
  std::vector<std::pair<double, double>> todo{{c.t_min(), c.t_max()}};
  chain.breaks.push_back(c.t_min());
  while (!todo.empty()) {
    const auto [a, b] = todo.back();
    todo.pop_back();
    const SplineCurve s = piece(c, a, b);
    std::array<Vec3, 4> span = hermite_span(s);
    const double d = span_deviation(s, span);
    const double m = cut(c, a, b);
    if (d > tolerance && m > a && m < b) {
      todo.push_back({m, b});
      todo.push_back({a, m});
      continue;
    }
    if (d > tolerance)  // an interval too short to cut in doubles: the curve is not finite there
      throw std::invalid_argument("the curve cannot be fitted within " + std::to_string(tolerance));
    if (!chain.spans.empty()) {
      // The left and right limits at a break of the curve: equal to rounding where it is
      // continuous (the spans then share the point exactly), apart where the knot breaks it.
      if (glm::length(span[0] - chain.spans.back()[3]) > tolerance)
        throw std::invalid_argument("the curve is broken in two at parameter " + std::to_string(a) +
                                    " (split it there first)");
      span[0] = chain.spans.back()[3];
    }
    chain.spans.push_back(span);
    chain.breaks.push_back(b);
    chain.deviation = std::max(chain.deviation, d);
    if (static_cast<int>(chain.spans.size()) > max_spans)
      throw std::invalid_argument("the curve needs more than " + std::to_string(max_spans) +
                                  " cubic spans within " + std::to_string(tolerance) +
                                  " (a larger tolerance needs fewer)");
  }
  return chain;
}

}  // namespace pl
