#include "core/curve/bspline_curve.hpp"

#include <algorithm>
#include <stdexcept>

#include "core/curve/curvature.hpp"
#include "core/math/bspline_basis.hpp"

namespace pl {

BSplineCurve::BSplineCurve(int degree, std::vector<double> knots, std::vector<Vec3> points)
    : p_(degree), knots_(std::move(knots)), points_(std::move(points)) {
  validate_knots(p_, knots_, points_.size());
}

std::vector<double> BSplineCurve::clamped_uniform_knots(int p, std::size_t n) {
  std::vector<double> u(n + p + 1);
  const std::size_t spans = n - p;
  for (std::size_t i = 0; i < u.size(); ++i) {
    const long k = static_cast<long>(i) - p;
    u[i] = k <= 0 ? 0.0 : k >= static_cast<long>(spans) ? 1.0 : double(k) / double(spans);
  }
  return u;
}

CurvePoint BSplineCurve::evaluate(double t) const {
  const SplineBasis b = spline_basis(p_, knots_, points_.size(), t);
  CurvePoint c{Vec3(0), Vec3(0), Vec3(0)};
  for (int r = 0; r <= p_; ++r) {
    const Vec3& q = points_[b.span - p_ + r];
    c.p += b.d0[r] * q;
    c.d1 += b.d1[r] * q;
    c.d2 += b.d2[r] * q;
  }
  return c;
}

double BSplineCurve::curvature(double t) const {
  return curve_curvature(evaluate(t));
}

void insert_knot(int p, std::vector<double>& U, std::vector<glm::dvec4>& P, double t) {
  const int k = find_span(p, U, P.size(), t);  // U[k] <= t <= U[k+1]
  std::vector<glm::dvec4> Q(P.size() + 1);
  for (int i = 0; i <= k - p; ++i) Q[i] = P[i];
  for (int i = k - p + 1; i <= k; ++i) {
    const double a = (t - U[i]) / (U[i + p] - U[i]);
    Q[i] = a * P[i] + (1 - a) * P[i - 1];
  }
  for (std::size_t i = k + 1; i < Q.size(); ++i) Q[i] = P[i - 1];
  U.insert(U.begin() + k + 1, t);
  P = std::move(Q);
}

void make_bezier_spans(int p, std::vector<double>& U, std::vector<glm::dvec4>& P) {
  // Every distinct knot value in [t_min, t_max], ends included, raised to multiplicity p.
  std::vector<double> values(U.begin() + p, U.begin() + static_cast<std::ptrdiff_t>(P.size()) + 1);
  values.erase(std::unique(values.begin(), values.end()), values.end());
  for (double v : values) {
    int m = static_cast<int>(std::count(U.begin(), U.end(), v));
    for (; m < p; ++m) insert_knot(p, U, P, v);
  }
}

void check_knot_insertion(int p, const std::vector<double>& knots, std::size_t count, double t) {
  if (!(t >= knots[p] && t <= knots[count]))
    throw std::invalid_argument("knot outside the curve's range");
  if (std::count(knots.begin(), knots.end(), t) >= p)
    throw std::invalid_argument("knot multiplicity would exceed the degree");
}

BSplineCurve BSplineCurve::inserted(double t) const {
  check_knot_insertion(p_, knots_, points_.size(), t);
  std::vector<double> U = knots_;
  std::vector<glm::dvec4> P;
  for (const Vec3& q : points_) P.emplace_back(q, 1.0);
  insert_knot(p_, U, P, t);
  std::vector<Vec3> out;
  for (const auto& q : P) out.emplace_back(q);
  return BSplineCurve(p_, std::move(U), std::move(out));
}

std::vector<BezierCurve> BSplineCurve::bezier_pieces() const {
  std::vector<double> U = knots_;
  std::vector<glm::dvec4> P;
  for (const Vec3& q : points_) P.emplace_back(q, 1.0);
  make_bezier_spans(p_, U, P);
  std::vector<BezierCurve> pieces;
  for (int s = p_; s < static_cast<int>(P.size()); ++s) {
    if (!(U[s] < U[s + 1])) continue;
    std::vector<Vec3> b;
    for (int r = 0; r <= p_; ++r) b.emplace_back(P[s - p_ + r]);
    pieces.emplace_back(std::move(b));
  }
  return pieces;
}

}  // namespace pl
