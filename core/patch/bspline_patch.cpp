#include "core/patch/bspline_patch.hpp"

#include <algorithm>
#include <cassert>
#include <stdexcept>

#include "core/curve/bspline_curve.hpp"
#include "core/curve/nurbs_curve.hpp"

namespace pl {

BSplinePatch::BSplinePatch(int p, int q, std::vector<double> ku, std::vector<double> kv,
                           std::size_t nu, std::size_t nv, std::vector<Vec3> points)
    : SplineGridPatch(std::move(points), SplineGrid(p, q, std::move(ku), std::move(kv), nu, nv)) {
  if (points_.size() != nu * nv)
    throw std::invalid_argument("a " + std::to_string(nu) + " x " + std::to_string(nv) +
                                " spline patch needs " + std::to_string(nu * nv) + " points, got " +
                                std::to_string(points_.size()));
}

void BSplinePatch::basis(Vec2 x, std::span<Jet> out) const {
  assert(out.size() == size());
  std::fill(out.begin(), out.end(), Jet(0.0));
  const auto l = grid_.local(x);
  for (int a = 0; a <= grid_.p(); ++a)
    for (int b = 0; b <= grid_.q(); ++b)
      out[(l.i0 + a) * grid_.nv() + l.j0 + b] = l.phi[a * (grid_.q() + 1) + b];
}

SurfaceJet BSplinePatch::evaluate(Vec2 x) const {
  // Only the (p+1)(q+1) non-zero functions: O(pq) instead of O(nu nv).
  const auto l = grid_.local(x);
  return grid_.combine(l, points_);
}

void BSplinePatch::influence(std::size_t k, std::span<const Vec2> xs, std::span<Jet> out) const {
  assert(k < size() && xs.size() == out.size());
  const int i = static_cast<int>(k / grid_.nv()), j = static_cast<int>(k % grid_.nv());
  for (std::size_t s = 0; s < xs.size(); ++s) {
    out[s] = Jet(0.0);
    if (!grid_.touches(k, xs[s])) continue;  // outside the support: no basis evaluation at all
    const auto l = grid_.local(xs[s]);
    out[s] = l.phi[(i - l.i0) * (grid_.q() + 1) + (j - l.j0)];
  }
}

namespace {
BezierCurve side_curve(int degree, const std::vector<double>& knots, std::vector<Vec3> pts) {
  BSplineCurve c(degree, knots, pts);
  const auto pieces = c.bezier_pieces();
  return pieces.size() == 1 ? pieces[0] : BezierCurve(std::move(pts));
}
}  // namespace

std::vector<BezierCurve> spline_boundary_curves(const SplineGrid& g, const std::vector<Vec3>& P) {
  const std::size_t nu = g.nu(), nv = g.nv();
  std::vector<Vec3> s0, s1, s3, s2;
  for (std::size_t i = 0; i < nu; ++i) s0.push_back(P[i * nv]), s2.push_back(P[i * nv + nv - 1]);
  for (std::size_t j = 0; j < nv; ++j) s3.push_back(P[j]), s1.push_back(P[(nu - 1) * nv + j]);
  // Only a clamped side starts at its first control point; other knot vectors are handled by the
  // Bézier extraction in side_curve.
  BezierCurve c0 = side_curve(g.p(), g.knots_u(), s0), c1 = side_curve(g.q(), g.knots_v(), s1);
  BezierCurve c2 = side_curve(g.p(), g.knots_u(), s2), c3 = side_curve(g.q(), g.knots_v(), s3);
  return {c0, c1, c2.reversed(), c3.reversed()};
}

Vec3 spline_boundary_point(const SplineGrid& g, const std::vector<Vec3>& points,
                           const std::vector<double>& weights, int side, double t) {
  // Unit square sides: 0 is v = 0 (u = t), 1 is u = 1 (v = t), 2 is v = 1 (u = 1 - t), 3 is
  // u = 0 (v = 1 - t).
  const bool along_u = side == 0 || side == 2;
  const double x = (side == 2 || side == 3) ? 1.0 - t : t;
  const std::size_t nu = g.nu(), nv = g.nv();
  const std::size_t n_along = along_u ? nu : nv, n_across = along_u ? nv : nu;
  const int deg_along = along_u ? g.p() : g.q(), deg_across = along_u ? g.q() : g.p();
  const auto& k_along = along_u ? g.knots_u() : g.knots_v();
  const auto& k_across = along_u ? g.knots_v() : g.knots_u();
  // The fixed cross parameter: the start or end of the cross knot range.
  const bool at_end = side == 1 || side == 2;
  const double fixed = at_end ? k_across[n_across] : k_across[deg_across];
  const bool rational = !weights.empty();
  std::vector<Vec3> side_points(n_along);
  std::vector<double> side_weights(n_along, 1.0);
  for (std::size_t a = 0; a < n_along; ++a) {
    std::vector<Vec3> wp(n_across), w(n_across);
    for (std::size_t c = 0; c < n_across; ++c) {
      const std::size_t k = along_u ? a * nv + c : c * nv + a;
      const double wk = rational ? weights[k] : 1.0;
      wp[c] = wk * points[k];
      w[c] = Vec3(wk, 0, 0);
    }
    const Vec3 hp = BSplineCurve(deg_across, k_across, wp).evaluate(fixed).p;
    const double hw = rational ? BSplineCurve(deg_across, k_across, w).evaluate(fixed).p.x : 1.0;
    side_points[a] = hp / hw;
    side_weights[a] = hw;
  }
  const double s = k_along[deg_along] + x * (k_along[n_along] - k_along[deg_along]);
  if (!rational) return BSplineCurve(deg_along, k_along, side_points).evaluate(s).p;
  return NurbsCurve(deg_along, k_along, side_points, side_weights).evaluate(s).p;
}

Vec3 BSplinePatch::boundary_point(int side, double t) const {
  return spline_boundary_point(grid_, points_, {}, side, t);
}

BSplinePatch BSplinePatch::inserted_u(double t) const {
  const std::size_t nu = grid_.nu(), nv = grid_.nv();
  std::vector<double> U;
  std::vector<Vec3> out((nu + 1) * nv);
  for (std::size_t j = 0; j < nv; ++j) {  // every u-row of the control net is one curve
    U = grid_.knots_u();
    std::vector<glm::dvec4> row;
    for (std::size_t i = 0; i < nu; ++i) row.emplace_back(points_[i * nv + j], 1.0);
    insert_knot(grid_.p(), U, row, t);
    for (std::size_t i = 0; i <= nu; ++i) out[i * nv + j] = Vec3(row[i]);
  }
  return BSplinePatch(grid_.p(), grid_.q(), U, grid_.knots_v(), nu + 1, nv, std::move(out));
}

BSplinePatch BSplinePatch::inserted_v(double t) const {
  const std::size_t nu = grid_.nu(), nv = grid_.nv();
  std::vector<double> V;
  std::vector<Vec3> out(nu * (nv + 1));
  for (std::size_t i = 0; i < nu; ++i) {
    V = grid_.knots_v();
    std::vector<glm::dvec4> col;
    for (std::size_t j = 0; j < nv; ++j) col.emplace_back(points_[i * nv + j], 1.0);
    insert_knot(grid_.q(), V, col, t);
    for (std::size_t j = 0; j <= nv; ++j) out[i * (nv + 1) + j] = Vec3(col[j]);
  }
  return BSplinePatch(grid_.p(), grid_.q(), grid_.knots_u(), V, nu, nv + 1, std::move(out));
}

}  // namespace pl
