#include "core/curve/bezier_curve.hpp"

#include <cassert>
#include <stdexcept>

#include "core/math/bernstein.hpp"

namespace pl {

BezierCurve::BezierCurve(std::vector<Vec3> control_points) : cp_(std::move(control_points)) {
  if (cp_.empty()) throw std::invalid_argument("a Bézier curve needs at least one control point");
}

Vec3 BezierCurve::point(double t) const {
  std::vector<Vec3> b = cp_;
  for (int r = 1; r <= degree(); ++r)
    for (int i = 0; i + r <= degree(); ++i) b[i] = (1 - t) * b[i] + t * b[i + 1];
  return b[0];
}

CurvePoint BezierCurve::evaluate(double t) const {
  const int n = degree();
  std::vector<double> d0(n + 1), d1(n + 1), d2(n + 1);
  bernstein_all_d2(n, t, d0, d1, d2);
  CurvePoint r{Vec3(0), Vec3(0), Vec3(0)};
  for (int i = 0; i <= n; ++i) {
    r.p += d0[i] * cp_[i];
    r.d1 += d1[i] * cp_[i];
    r.d2 += d2[i] * cp_[i];
  }
  return r;
}

BezierCurve BezierCurve::elevated() const {
  const int n = degree();
  std::vector<Vec3> q(n + 2);
  q[0] = cp_[0];
  q[n + 1] = cp_[n];
  for (int i = 1; i <= n; ++i) {
    const double a = static_cast<double>(i) / (n + 1);
    q[i] = a * cp_[i - 1] + (1 - a) * cp_[i];
  }
  return BezierCurve(std::move(q));
}

BezierCurve BezierCurve::elevated_to(int target) const {
  assert(target >= degree());
  BezierCurve c = *this;
  while (c.degree() < target) c = c.elevated();
  return c;
}

std::pair<BezierCurve, BezierCurve> BezierCurve::split(double t) const {
  const int n = degree();
  std::vector<Vec3> b = cp_, left(n + 1), right(n + 1);
  left[0] = b[0];
  right[n] = b[n];
  for (int r = 1; r <= n; ++r) {
    for (int i = 0; i + r <= n; ++i) b[i] = (1 - t) * b[i] + t * b[i + 1];
    left[r] = b[0];
    right[n - r] = b[n - r];
  }
  return {BezierCurve(std::move(left)), BezierCurve(std::move(right))};
}

BezierCurve BezierCurve::reversed() const {
  return BezierCurve({cp_.rbegin(), cp_.rend()});
}

BezierCurve BezierCurve::derivative() const {
  const int n = degree();
  if (n == 0) return BezierCurve({Vec3(0)});
  std::vector<Vec3> d(n);
  for (int i = 0; i < n; ++i) d[i] = static_cast<double>(n) * (cp_[i + 1] - cp_[i]);
  return BezierCurve(std::move(d));
}

}  // namespace pl
