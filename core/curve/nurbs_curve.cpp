#include "core/curve/nurbs_curve.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/curve/bspline_curve.hpp"
#include "core/curve/curvature.hpp"
#include "core/math/bspline_basis.hpp"

namespace pl {

void validate_weights(const std::vector<double>& w, std::size_t n) {
  if (w.size() != n)
    throw std::invalid_argument("expected " + std::to_string(n) + " weights, got " +
                                std::to_string(w.size()));
  for (std::size_t i = 0; i < w.size(); ++i)
    if (!(w[i] > 0) || !std::isfinite(w[i]))
      throw std::invalid_argument("weight " + std::to_string(i) + " must be positive and finite");
}

NurbsCurve::NurbsCurve(int degree, std::vector<double> knots, std::vector<Vec3> points,
                       std::vector<double> weights)
    : p_(degree),
      knots_(std::move(knots)),
      points_(std::move(points)),
      weights_(std::move(weights)) {
  validate_knots(p_, knots_, points_.size());
  validate_weights(weights_, points_.size());
}

NurbsCurve NurbsCurve::circle(Vec3 c, Vec3 x, Vec3 y, double r) {
  const double h = std::sqrt(0.5);
  std::vector<Vec3> pts;
  std::vector<double> w;
  // Corners of the circumscribed square carry weight cos(45 deg): each quarter is an exact arc.
  const double cx[9] = {1, 1, 0, -1, -1, -1, 0, 1, 1}, cy[9] = {0, 1, 1, 1, 0, -1, -1, -1, 0};
  for (int i = 0; i < 9; ++i) {
    pts.push_back(c + r * (cx[i] * x + cy[i] * y));
    w.push_back(i % 2 ? h : 1.0);
  }
  return NurbsCurve(2, {0, 0, 0, .25, .25, .5, .5, .75, .75, 1, 1, 1}, pts, w);
}

NurbsCurve NurbsCurve::half_circle(Vec3 c, Vec3 x, Vec3 y, double r) {
  const double h = std::sqrt(0.5);
  return NurbsCurve(2, {0, 0, 0, .5, .5, 1, 1, 1},
                    {c + r * x, c + r * (x + y), c + r * y, c + r * (y - x), c - r * x},
                    {1, h, 1, h, 1});
}

CurvePoint NurbsCurve::evaluate(double t) const {
  const SplineBasis b = spline_basis(p_, knots_, points_.size(), t);
  // Homogeneous A = sum N w P and W = sum N w; C = A / W by the quotient rule.
  Vec3 a0(0), a1(0), a2(0);
  double w0 = 0, w1 = 0, w2 = 0;
  for (int r = 0; r <= p_; ++r) {
    const int i = b.span - p_ + r;
    const double w = weights_[i];
    a0 += b.d0[r] * w * points_[i];
    a1 += b.d1[r] * w * points_[i];
    a2 += b.d2[r] * w * points_[i];
    w0 += b.d0[r] * w, w1 += b.d1[r] * w, w2 += b.d2[r] * w;
  }
  CurvePoint c;
  c.p = a0 / w0;
  c.d1 = (a1 - w1 * c.p) / w0;
  c.d2 = (a2 - 2 * w1 * c.d1 - w2 * c.p) / w0;
  return c;
}

double NurbsCurve::curvature(double t) const {
  return curve_curvature(evaluate(t));
}

NurbsCurve NurbsCurve::inserted(double t) const {
  check_knot_insertion(p_, knots_, points_.size(), t);
  std::vector<double> U = knots_;
  std::vector<glm::dvec4> P;
  for (std::size_t i = 0; i < points_.size(); ++i)
    P.emplace_back(weights_[i] * points_[i], weights_[i]);
  insert_knot(p_, U, P, t);
  std::vector<Vec3> pts;
  std::vector<double> w;
  for (const auto& q : P) {
    pts.emplace_back(Vec3(q) / q.w);
    w.push_back(q.w);
  }
  return NurbsCurve(p_, std::move(U), std::move(pts), std::move(w));
}

}  // namespace pl
