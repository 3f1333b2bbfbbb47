#include "core/cad/cad_spline.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <glm/vec4.hpp>
#include <stdexcept>
#include <string>

#include "core/curve/bspline_curve.hpp"

namespace pl {

namespace {

int find_cad_span(int p, std::span<const double> U, std::size_t n, double t) {
  if (t >= U[n]) {  // the end of the range: the last non-empty span
    int i = static_cast<int>(n) - 1;
    while (i > p && U[i] == U[i + 1]) --i;
    return i;
  }
  if (t <= U[p]) {
    int i = p;
    while (i < static_cast<int>(n) - 1 && U[i] == U[i + 1]) ++i;
    return i;
  }
  const auto it = std::upper_bound(U.begin() + p, U.begin() + static_cast<std::ptrdiff_t>(n), t);
  return static_cast<int>(it - U.begin()) - 1;
}

void check_clamped(int p, const std::vector<double>& U, std::size_t n, const char* what) {
  if (p < 1 || p > kMaxCadDegree)
    throw std::invalid_argument(std::string(what) + ": degree " + std::to_string(p) +
                                " outside 1..25");
  if (n < static_cast<std::size_t>(p) + 1 || U.size() != n + p + 1)
    throw std::invalid_argument(std::string(what) + ": knot and point counts do not match");
  for (std::size_t i = 1; i < U.size(); ++i)
    if (!(U[i] >= U[i - 1])) throw std::invalid_argument(std::string(what) + ": knots decrease");
  for (int i = 0; i <= p; ++i)
    if (U[i] != 0.0 || U[U.size() - 1 - i] != 1.0)
      throw std::invalid_argument(std::string(what) + ": knots are not clamped over [0, 1]");
  for (const KnotRun& r : knot_runs(U))
    if (r.value > 0 && r.value < 1 && r.multiplicity > p)
      throw std::invalid_argument(std::string(what) + ": interior knot multiplicity > degree");
}

}  // namespace

CadBasis cad_basis(int p, std::span<const double> U, std::size_t n, double t) {
  CadBasis b;
  const int s = b.span = find_cad_span(p, U, n, t);
  // ndu as in the NURBS book (A2.3): basis values of every degree and the knot differences.
  std::vector<double> left(p + 1), right(p + 1), ndu((p + 1) * (p + 1));
  auto at = [&](int r, int c) -> double& { return ndu[r * (p + 1) + c]; };
  at(0, 0) = 1;
  for (int j = 1; j <= p; ++j) {
    left[j] = t - U[s + 1 - j];
    right[j] = U[s + j] - t;
    double saved = 0;
    for (int r = 0; r < j; ++r) {
      at(j, r) = right[r + 1] + left[j - r];  // lower triangle: knot differences
      const double temp = at(r, j - 1) / at(j, r);
      at(r, j) = saved + right[r + 1] * temp;
      saved = left[j - r] * temp;
    }
    at(j, j) = saved;
  }
  b.value.resize(p + 1);
  b.derivative.resize(p + 1);
  for (int r = 0; r <= p; ++r) b.value[r] = at(r, p);
  // First derivative: N'_{i,p} = p (N_{i,p-1} / (u_{i+p} - u_i) - N_{i+1,p-1} / (u_{i+p+1} -
  // u_{i+1})), with the degree p-1 values in column p-1 and the differences in row p.
  for (int r = 0; r <= p; ++r) {
    double d = 0;
    if (r >= 1) d += at(r - 1, p - 1) / at(p, r - 1);
    if (r <= p - 1) d -= at(r, p - 1) / at(p, r);
    b.derivative[r] = p * d;
  }
  return b;
}

std::vector<KnotRun> knot_runs(std::span<const double> U) {
  std::vector<KnotRun> runs;
  for (double k : U) {
    if (!runs.empty() && runs.back().value == k)
      ++runs.back().multiplicity;
    else
      runs.push_back({k, 1});
  }
  return runs;
}

CadCurve CadCurve::from_bezier(const BezierCurve& b) {
  CadCurve c;
  c.degree = b.degree();
  c.points = b.control_points();
  c.knots.assign(c.degree + 1, 0.0);
  c.knots.resize(2 * (c.degree + 1), 1.0);
  return c;
}

CurvePoint CadCurve::evaluate(double t) const {
  const CadBasis b = cad_basis(degree, knots, points.size(), t);
  CurvePoint out{Vec3(0), Vec3(0), Vec3(0)};
  for (int r = 0; r <= degree; ++r) {
    out.p += b.value[r] * points[b.span - degree + r];
    out.d1 += b.derivative[r] * points[b.span - degree + r];
  }
  return out;
}

CadCurve CadCurve::reversed() const {
  CadCurve c;
  c.degree = degree;
  c.points.assign(points.rbegin(), points.rend());
  for (auto it = knots.rbegin(); it != knots.rend(); ++it) c.knots.push_back(1.0 - *it);
  return c;
}

CadCurve CadCurve::elevated_to(int p) const {
  if (p < degree) throw std::invalid_argument("cannot lower a curve's degree");
  if (p == degree) return *this;
  if (points.size() == static_cast<std::size_t>(degree) + 1)  // one Bézier span: exact formula
    return from_bezier(BezierCurve(points).elevated_to(p));
  // Several spans: the elevated curve lies in the space of degree p with every multiplicity
  // raised by p - degree; interpolation at that space's Greville abscissae (Schoenberg-Whitney
  // holds there) recovers it exactly up to rounding.
  CadCurve c;
  c.degree = p;
  for (const KnotRun& r : knot_runs(knots)) {
    const bool end = r.value == 0.0 || r.value == 1.0;
    c.knots.insert(c.knots.end(), end ? p + 1 : r.multiplicity + (p - degree), r.value);
  }
  const std::size_t n = c.knots.size() - p - 1;
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n, n);
  Eigen::MatrixXd rhs(n, 3);
  for (std::size_t i = 0; i < n; ++i) {
    double g = 0;
    for (int k = 1; k <= p; ++k) g += c.knots[i + k];
    g /= p;
    const CadBasis b = cad_basis(p, c.knots, n, g);
    for (int r = 0; r <= p; ++r) A(i, b.span - p + r) = b.value[r];
    const Vec3 q = evaluate(g).p;
    rhs.row(i) << q.x, q.y, q.z;
  }
  const Eigen::MatrixXd x = A.partialPivLu().solve(rhs);
  for (std::size_t i = 0; i < n; ++i) c.points.emplace_back(x(i, 0), x(i, 1), x(i, 2));
  c.points.front() = points.front();  // the ends are interpolated exactly
  c.points.back() = points.back();
  return c;
}

CadCurve CadCurve::refined_to(const std::vector<double>& target) const {
  std::vector<double> U = knots;
  std::vector<glm::dvec4> P;
  for (const Vec3& q : points) P.emplace_back(q, 1.0);
  for (const KnotRun& r : knot_runs(target)) {
    const int have = static_cast<int>(std::count(U.begin(), U.end(), r.value));
    if (have > r.multiplicity)
      throw std::invalid_argument("refined_to: the target knots do not contain the curve's");
    for (int k = have; k < r.multiplicity; ++k) insert_knot(degree, U, P, r.value);
  }
  CadCurve c;
  c.degree = degree;
  c.knots = std::move(U);
  for (const auto& q : P) c.points.emplace_back(q);
  return c;
}

CadSurface::Jet1 CadSurface::evaluate(double u, double v) const {
  const CadBasis bu = cad_basis(degree_u, knots_u, nu, u);
  const CadBasis bv = cad_basis(degree_v, knots_v, nv, v);
  glm::dvec4 s(0), su(0), sv(0);
  for (int a = 0; a <= degree_u; ++a) {
    const std::size_t i = bu.span - degree_u + a;
    for (int b = 0; b <= degree_v; ++b) {
      const std::size_t j = bv.span - degree_v + b;
      const double w = weights.empty() ? 1.0 : weights[i * nv + j];
      const glm::dvec4 h(w * points[i * nv + j], w);
      s += bu.value[a] * bv.value[b] * h;
      su += bu.derivative[a] * bv.value[b] * h;
      sv += bu.value[a] * bv.derivative[b] * h;
    }
  }
  Jet1 out;
  out.p = Vec3(s) / s.w;
  out.su = (Vec3(su) - su.w * out.p) / s.w;
  out.sv = (Vec3(sv) - sv.w * out.p) / s.w;
  return out;
}

CadCurve CadSurface::boundary(int side) const {
  if (rational()) throw std::invalid_argument("boundary(): the surface is rational");
  CadCurve c;
  const bool along_u = side == 0 || side == 2;
  c.degree = along_u ? degree_u : degree_v;
  c.knots = along_u ? knots_u : knots_v;
  if (along_u) {
    const std::size_t j = side == 0 ? 0 : nv - 1;
    for (std::size_t i = 0; i < nu; ++i) c.points.push_back(at(i, j));
  } else {
    const std::size_t i = side == 3 ? 0 : nu - 1;
    for (std::size_t j = 0; j < nv; ++j) c.points.push_back(at(i, j));
  }
  return c;
}

void validate_cad_surface(const CadSurface& s) {
  check_clamped(s.degree_u, s.knots_u, s.nu, "surface u");
  check_clamped(s.degree_v, s.knots_v, s.nv, "surface v");
  if (s.points.size() != s.nu * s.nv)
    throw std::invalid_argument("surface: point count does not match the knots");
  for (const Vec3& p : s.points)
    if (!finite(p)) throw std::invalid_argument("surface: a control point is not finite");
  if (!s.weights.empty()) {
    if (s.weights.size() != s.points.size())
      throw std::invalid_argument("surface: weight count does not match the points");
    for (double w : s.weights)
      if (!(w > 0) || !std::isfinite(w))
        throw std::invalid_argument("surface: weights must be positive and finite");
  }
}

std::vector<double> merge_knots(int p, const std::vector<double>& a, const std::vector<double>& b) {
  const auto ra = knot_runs(a), rb = knot_runs(b);
  std::vector<KnotRun> all;
  std::size_t i = 0, j = 0;
  while (i < ra.size() || j < rb.size()) {
    if (j >= rb.size() || (i < ra.size() && ra[i].value < rb[j].value)) {
      all.push_back(ra[i++]);
    } else if (i >= ra.size() || rb[j].value < ra[i].value) {
      all.push_back(rb[j++]);
    } else {
      all.push_back({ra[i].value, std::max(ra[i].multiplicity, rb[j].multiplicity)});
      ++i, ++j;
    }
  }
  std::vector<double> U;
  for (const KnotRun& r : all) {
    const bool end = r.value == 0.0 || r.value == 1.0;
    U.insert(U.end(), end ? p + 1 : std::min(r.multiplicity, p), r.value);
  }
  return U;
}

std::vector<double> uniform_knots(int p, int spans) {
  std::vector<double> U(p + 1, 0.0);
  for (int k = 1; k < spans; ++k) U.push_back(static_cast<double>(k) / spans);
  U.insert(U.end(), p + 1, 1.0);
  return U;
}

}  // namespace pl
