#include "core/patch/transfinite/ribbon_set.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

#include "core/math/bspline_basis.hpp"
#include "core/patch/transfinite/vec_jet.hpp"

namespace pl::transfinite {

UnitCurve::UnitCurve(SplineCurve spline) : spline_(std::move(spline)) {
  validate_spline_curve(spline_);
  const int p = spline_.degree;
  bezier_ = !spline_.rational() && spline_.points.size() == std::size_t(p + 1) &&
            spline_.t_min() == 0 && spline_.t_max() == 1 && spline_.knots.front() == 0 &&
            spline_.knots.back() == 1;
}

CurvePoint UnitCurve::at(double s) const {
  if (bezier_) {
    // de Casteljau down to the last three points b0, b1, b2 (degree >= 2) or two (degree 1).
    const auto& cp = spline_.points;
    const int d = spline_.degree;
    Vec3 b[kMaxSplineDegree + 1];
    for (int k = 0; k <= d; ++k) b[k] = cp[std::size_t(k)];
    const double t = s, u = 1 - s;
    for (int level = d; level > 2; --level)
      for (int k = 0; k < level; ++k) b[k] = u * b[k] + t * b[k + 1];
    if (d == 1) return {u * b[0] + t * b[1], b[1] - b[0], Vec3(0)};
    const Vec3 e0 = b[1] - b[0], e1 = b[2] - b[1];
    return {u * (u * b[0] + t * b[1]) + t * (u * b[1] + t * b[2]), double(d) * (u * e0 + t * e1),
            double(d * (d - 1)) * (e1 - e0)};
  }
  return at_by_basis(s);
}

CurvePoint UnitCurve::at_by_basis(double s) const {
  const double a = spline_.t_min(), b = spline_.t_max();
  if (a == 0 && b == 1) return evaluate(spline_, s);
  const double len = b - a;
  CurvePoint c = evaluate(spline_, a + s * len);
  c.d1 *= len;
  c.d2 *= len * len;
  return c;
}

namespace {
// x clamped to [lo, hi]. Within rounding of a bound (a point on a side whose d comes out as
// -1e-17) only the value is clamped: the derivatives are those of the side itself, which is what
// keeps the patch G1 to its ribbons there.
Jet clamped(Jet x, double lo, double hi) {
  constexpr double kRounding = 1e-12;
  if (x.f < lo) x = x.f < lo - kRounding ? Jet(lo) : Jet(lo, x.fu, x.fv, x.fuu, x.fuv, x.fvv);
  if (x.f > hi) x = x.f > hi + kRounding ? Jet(hi) : Jet(hi, x.fu, x.fv, x.fuu, x.fuv, x.fvv);
  return x;
}
}  // namespace

Jet gamma(const Jet& d) {
  const double q = 2 * d.f + 1;
  return chain(d, d.f / q, 1 / (q * q), -4 / (q * q * q));
}

Jet hermite_blend(const Jet& t) {
  const double x = t.f, y = 1 - x;
  return chain(t, y * y * y + 3 * y * y * x, -6 * x + 6 * x * x, -6 + 12 * x);
}

RibbonSet::RibbonSet(std::vector<RibbonCurves> sides, TwistEstimate twists)
    : sides_(std::move(sides)), twists_(twists) {
  if (sides_.size() < 3) throw std::invalid_argument("a ribbon patch needs at least 3 sides");
  const int n = size();
  corners_.resize(n);
  constexpr double h = 1.0e-4;
  for (int i = 0; i < n; ++i) {
    const RibbonCurves& a = side(i);
    const RibbonCurves& b = side(i + 1);
    const CurvePoint end = a.curve.at(1), start = b.curve.at(0);
    CornerData& c = corners_[i];
    c.point = end.p;
    c.t1 = -end.d1;
    c.t2 = start.d1;
    if (twists_ == TwistEstimate::Exact) {
      c.twist1 = -a.cross.at(1).d1;
      c.twist2 = b.cross.at(0).d1;
    } else {
      c.twist1 = (a.cross.at_by_basis(1 - h).p - a.cross.at_by_basis(1).p) / h;
      c.twist2 = (b.cross.at_by_basis(h).p - b.cross.at_by_basis(0).p) / h;
    }
  }
}

SurfaceJet RibbonSet::side_interpolant(int i, const Jet& s, const Jet& d) const {
  const RibbonCurves& r = side(i);
  const Jet sc = clamped(s, 0, 1);
  const Jet g = clamped(gamma(d), 0, std::numeric_limits<double>::infinity());
  const SurfaceJet p = compose(r.curve.at(sc.f), sc);
  const SurfaceJet c = compose(r.cross.at(sc.f), sc);
  return p + g * c;
}

SurfaceJet RibbonSet::corner_correction(int i, const Jet& a, const Jet& b) const {
  const CornerData& c = corner(i);
  const Jet ga = clamped(gamma(a), 0, 1), gb = clamped(gamma(b), 0, 1);
  SurfaceJet q = constant_jet(c.point) + ga * c.t1 + gb * c.t2;
  const Jet sum = ga + gb;
  if (std::abs(sum.f) < 1e-8) return q;
  const Jet r = ga * gb / sum;
  q += (r * ga) * c.twist2;
  q += (r * gb) * c.twist1;
  return q;
}

SurfaceJet RibbonSet::corner_interpolant(int i, const std::vector<Jet>& s) const {
  const Jet& si = s[wrap(i)];
  const Jet& sn = s[wrap(i + 1)];
  const Jet one_minus = 1.0 - si;
  return side_interpolant(i, si, sn) + side_interpolant(i + 1, sn, one_minus) -
         corner_correction(i, one_minus, sn);
}

}  // namespace pl::transfinite
