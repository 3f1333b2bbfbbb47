#include "core/curve/spline_curve.hpp"

#include <Eigen/SparseCore>
#include <Eigen/SparseLU>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/curve/bspline_curve.hpp"
#include "core/curve/nurbs_curve.hpp"
#include "core/math/bspline_basis.hpp"

namespace pl {

namespace {

std::vector<glm::dvec4> homogeneous(const SplineCurve& c) {
  std::vector<glm::dvec4> h;
  h.reserve(c.points.size());
  for (std::size_t i = 0; i < c.points.size(); ++i) {
    const double w = c.weight(i);
    h.emplace_back(w * c.points[i], w);
  }
  return h;
}

SplineCurve from_homogeneous(int p, std::vector<double> knots, const std::vector<glm::dvec4>& h,
                             bool rational) {
  SplineCurve c;
  c.degree = p;
  c.knots = std::move(knots);
  for (const auto& q : h) {
    c.points.emplace_back(rational ? Vec3(q) / q.w : Vec3(q));
    if (rational) c.weights.push_back(q.w);
  }
  return c;
}

// How many knots equal t, in a non-decreasing knot vector: O(log n), so that loops over the knots
// stay linear in their number.
int multiplicity(const std::vector<double>& U, double t) {
  const auto [lo, hi] = std::equal_range(U.begin(), U.end(), t);
  return static_cast<int>(hi - lo);
}

}  // namespace

void validate_spline_curve(const SplineCurve& c) {
  const int p = c.degree;
  const std::size_t n = c.points.size();
  if (p < 1 || p > kMaxSplineDegree)
    throw std::invalid_argument("degree must be between 1 and " + std::to_string(kMaxSplineDegree) +
                                ", got " + std::to_string(p));
  if (n < std::size_t(p) + 1)
    throw std::invalid_argument("degree " + std::to_string(p) + " needs at least " +
                                std::to_string(p + 1) + " points, got " + std::to_string(n));
  if (c.knots.size() != n + p + 1)
    throw std::invalid_argument("expected " + std::to_string(n + p + 1) +
                                " knots (points + degree + 1), got " +
                                std::to_string(c.knots.size()));
  for (std::size_t i = 0; i < c.knots.size(); ++i) {
    if (!std::isfinite(c.knots[i]))
      throw std::invalid_argument("knot " + std::to_string(i) + " is not finite");
    if (i > 0 && c.knots[i] < c.knots[i - 1])
      throw std::invalid_argument("knots must not decrease (knot " + std::to_string(i) + ")");
    // Knots 0 .. i do not decrease, so this is a run of p + 2 equal knots ending at i.
    if (i > std::size_t(p) && c.knots[i] == c.knots[i - p - 1])
      throw std::invalid_argument("knot " + std::to_string(i) +
                                  " has multiplicity above degree + 1");
  }
  if (!(c.t_min() < c.t_max())) throw std::invalid_argument("the knots give an empty range");
  if (!c.weights.empty()) validate_weights(c.weights, n);
}

std::vector<std::pair<double, double>> spline_spans(const SplineCurve& c) {
  std::vector<std::pair<double, double>> spans;
  for (std::size_t s = c.degree; s < c.points.size(); ++s)
    if (c.knots[s] < c.knots[s + 1]) spans.emplace_back(c.knots[s], c.knots[s + 1]);
  return spans;
}

CurvePoint evaluate_spline(int p, std::span<const double> knots, std::span<const Vec3> points,
                           std::span<const double> weights, double t) {
  int span = -1;
  return evaluate_spline(p, knots, points, weights, t, span);
}

CurvePoint evaluate_spline(int p, std::span<const double> knots, std::span<const Vec3> points,
                           std::span<const double> weights, double t, int& span) {
  span = find_span(p, knots, points.size(), t, span);
  const SplineBasis b = spline_basis_at(p, knots, span, t);
  Vec3 a0(0), a1(0), a2(0);
  double w0 = 0, w1 = 0, w2 = 0;
  for (int r = 0; r <= p; ++r) {
    const std::size_t i = b.span - p + r;
    const double w = weights.empty() ? 1.0 : weights[i];
    a0 += (b.d0[r] * w) * points[i];
    a1 += (b.d1[r] * w) * points[i];
    a2 += (b.d2[r] * w) * points[i];
    w0 += b.d0[r] * w, w1 += b.d1[r] * w, w2 += b.d2[r] * w;
  }
  if (weights.empty()) return {a0, a1, a2};
  // C = A / W by the quotient rule.
  CurvePoint r;
  r.p = a0 / w0;
  r.d1 = (a1 - w1 * r.p) / w0;
  r.d2 = (a2 - 2 * w1 * r.d1 - w2 * r.p) / w0;
  return r;
}

CurvePoint evaluate(const SplineCurve& c, double t) {
  return evaluate_spline(c.degree, c.knots, c.points, c.weights, t);
}

SplineCurve knot_inserted(const SplineCurve& c, double t) {
  if (!(t > c.t_min() && t < c.t_max()))
    throw std::invalid_argument("a knot is inserted strictly inside the curve's range");
  if (multiplicity(c.knots, t) >= c.degree + 1)
    throw std::invalid_argument("the knot already has multiplicity degree + 1");
  std::vector<double> U = c.knots;
  std::vector<glm::dvec4> h = homogeneous(c);
  insert_knot(c.degree, U, h, t);
  return from_homogeneous(c.degree, std::move(U), h, c.rational());
}

SplineCurve clamped(const SplineCurve& c) {
  const int p = c.degree;
  std::vector<double> U = c.knots;
  std::vector<glm::dvec4> h = homogeneous(c);
  const double a = c.t_min(), b = c.t_max();
  // Raise both ends to multiplicity p; the knots and points outside then no longer touch the
  // curve on [a, b] and are dropped.
  for (int m = multiplicity(U, a); m < p; ++m) insert_knot(p, U, h, a);
  for (int m = multiplicity(U, b); m < p; ++m) insert_knot(p, U, h, b);
  const int last_a = static_cast<int>(std::upper_bound(U.begin(), U.end(), a) - U.begin()) - 1;
  const int first_b = static_cast<int>(std::lower_bound(U.begin(), U.end(), b) - U.begin());
  const int drop_front = std::max(0, last_a - p);
  // Points whose support reaches into [a, b]: index drop_front .. first_b - 1.
  const int keep = first_b - drop_front;
  std::vector<double> V(p + 1, a);
  V.insert(V.end(), U.begin() + last_a + 1, U.begin() + first_b);
  V.insert(V.end(), p + 1, b);
  std::vector<glm::dvec4> q(h.begin() + drop_front, h.begin() + drop_front + keep);
  return from_homogeneous(p, std::move(V), q, c.rational());
}

SplineCurve degree_elevated(const SplineCurve& c0) {
  const SplineCurve c = clamped(c0);
  const int p = c.degree, q = p + 1;
  if (q > kMaxSplineDegree)
    throw std::invalid_argument("the degree is already " + std::to_string(kMaxSplineDegree));
  // The knots of degree p + 1: every distinct value once more, so every break keeps its
  // continuity; the old spline lies in this space, so collocation reproduces it exactly.
  std::vector<double> V;
  for (std::size_t i = 0; i < c.knots.size(); ++i) {
    V.push_back(c.knots[i]);
    if (i + 1 == c.knots.size() || c.knots[i + 1] != c.knots[i]) {
      if (multiplicity(c.knots, c.knots[i]) == p + 1 && i + 1 != c.knots.size() &&
          i + 1 != std::size_t(p + 1))
        throw std::invalid_argument("the curve is broken at knot " + std::to_string(c.knots[i]) +
                                    "; split it first");
      V.push_back(c.knots[i]);
    }
  }
  const std::size_t n = V.size() - q - 1;
  // Collocation at the Greville abscissae: the matrix is totally positive and banded.
  Eigen::SparseMatrix<double> A(n, n);
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::MatrixXd rhs(n, 4);
  for (std::size_t i = 0; i < n; ++i) {
    double tau = 0;
    for (int k = 1; k <= q; ++k) tau += V[i + k];
    tau /= q;
    const SplineBasis b = spline_basis(q, V, n, tau);
    for (int r = 0; r <= q; ++r)
      if (b.d0[r] != 0) entries.emplace_back(i, b.span - q + r, b.d0[r]);
    const SplineBasis old = spline_basis(p, c.knots, c.points.size(), tau);
    glm::dvec4 h(0);
    for (int r = 0; r <= p; ++r) {
      const std::size_t j = old.span - p + r;
      const double w = c.weight(j);
      h += old.d0[r] * glm::dvec4(w * c.points[j], w);
    }
    for (int k = 0; k < 4; ++k) rhs(i, k) = h[k];
  }
  A.setFromTriplets(entries.begin(), entries.end());
  Eigen::SparseLU<Eigen::SparseMatrix<double>> lu;
  lu.compute(A);
  if (lu.info() != Eigen::Success) throw std::invalid_argument("degree elevation failed");
  const Eigen::MatrixXd x = lu.solve(rhs);
  std::vector<glm::dvec4> h(n);
  for (std::size_t i = 0; i < n; ++i) h[i] = {x(i, 0), x(i, 1), x(i, 2), x(i, 3)};
  // The end points are interpolated exactly by a clamped spline: keep them bit for bit.
  h.front() = homogeneous(c).front();
  h.back() = homogeneous(c).back();
  return from_homogeneous(q, std::move(V), h, c.rational());
}

std::pair<SplineCurve, SplineCurve> split_at(const SplineCurve& c, double t) {
  if (!(t > c.t_min() && t < c.t_max()))
    throw std::invalid_argument("a curve is split strictly inside its range");
  const int p = c.degree;
  std::vector<double> U = c.knots;
  std::vector<glm::dvec4> h = homogeneous(c);
  for (int m = multiplicity(U, t); m < p + 1; ++m) insert_knot(p, U, h, t);
  // Now t has multiplicity p + 1: the points before it define the left piece, the rest the right.
  const int first_t = static_cast<int>(std::lower_bound(U.begin(), U.end(), t) - U.begin());
  std::vector<double> left_knots(U.begin(), U.begin() + first_t + p + 1);
  std::vector<double> right_knots(U.begin() + first_t, U.end());
  const std::size_t n_left = left_knots.size() - p - 1;
  std::vector<glm::dvec4> hl(h.begin(), h.begin() + n_left), hr(h.begin() + n_left, h.end());
  return {clamped(from_homogeneous(p, std::move(left_knots), hl, c.rational())),
          clamped(from_homogeneous(p, std::move(right_knots), hr, c.rational()))};
}

SplineCurve reversed(const SplineCurve& c) {
  SplineCurve r = c;
  const double s = c.t_min() + c.t_max();
  for (std::size_t i = 0; i < c.knots.size(); ++i) r.knots[i] = s - c.knots[c.knots.size() - 1 - i];
  std::reverse(r.points.begin(), r.points.end());
  std::reverse(r.weights.begin(), r.weights.end());
  return r;
}

}  // namespace pl
