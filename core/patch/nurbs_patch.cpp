#include "core/patch/nurbs_patch.hpp"

#include <algorithm>
#include <cassert>
#include <stdexcept>

#include "core/curve/bspline_curve.hpp"
#include "core/curve/nurbs_curve.hpp"
#include "core/patch/bspline_patch.hpp"

namespace pl {

NurbsPatch::NurbsPatch(int p, int q, std::vector<double> ku, std::vector<double> kv, std::size_t nu,
                       std::size_t nv, std::vector<Vec3> points, std::vector<double> weights)
    : SplineGridPatch(std::move(points), SplineGrid(p, q, std::move(ku), std::move(kv), nu, nv)),
      weights_(std::move(weights)) {
  if (points_.size() != nu * nv)
    throw std::invalid_argument("a " + std::to_string(nu) + " x " + std::to_string(nv) +
                                " NURBS patch needs " + std::to_string(nu * nv) + " points, got " +
                                std::to_string(points_.size()));
  validate_weights(weights_, nu * nv);
}

NurbsPatch NurbsPatch::sphere(Vec3 c, double r) {
  // Tensor product of a half circle (radius rho_i, height z_i) and a unit full circle: points
  // rho_i * circle_j + z_i, weights multiply.
  const NurbsCurve mer = NurbsCurve::half_circle(Vec3(0), Vec3(0, 0, -1), Vec3(1, 0, 0), r);
  const NurbsCurve ring = NurbsCurve::circle(Vec3(0), Vec3(1, 0, 0), Vec3(0, 1, 0), 1.0);
  std::vector<Vec3> pts;
  std::vector<double> w;
  for (std::size_t i = 0; i < 5; ++i)
    for (std::size_t j = 0; j < 9; ++j) {
      const Vec3 m = mer.control_points()[i], g = ring.control_points()[j];
      pts.push_back(c + Vec3(m.x * g.x, m.x * g.y, m.z));
      w.push_back(mer.weights()[i] * ring.weights()[j]);
    }
  return NurbsPatch(2, 2, mer.knots(), ring.knots(), 5, 9, std::move(pts), std::move(w));
}

NurbsPatch NurbsPatch::cylinder(Vec3 b, double r, double h) {
  const NurbsCurve ring = NurbsCurve::circle(b, Vec3(1, 0, 0), Vec3(0, 1, 0), r);
  std::vector<Vec3> pts;
  std::vector<double> w;
  for (std::size_t i = 0; i < 9; ++i)
    for (int j = 0; j < 2; ++j) {
      pts.push_back(ring.control_points()[i] + Vec3(0, 0, j * h));
      w.push_back(ring.weights()[i]);
    }
  return NurbsPatch(2, 1, ring.knots(), {0, 0, 1, 1}, 9, 2, std::move(pts), std::move(w));
}

namespace {
// The non-zero rational functions at x: local polynomial basis times weights over their sum.
SplineGrid::Local rational_local(const SplineGrid& g, const std::vector<double>& w, Vec2 x) {
  SplineGrid::Local l = g.local(x);
  const int m = (g.p() + 1) * (g.q() + 1);
  Jet W(0.0);
  for (int a = 0; a < m; ++a) {
    l.phi[a] *= w[(l.i0 + a / (g.q() + 1)) * g.nv() + l.j0 + a % (g.q() + 1)];
    W += l.phi[a];
  }
  const Jet inv = reciprocal(W);
  for (int a = 0; a < m; ++a) l.phi[a] = l.phi[a] * inv;
  return l;
}
}  // namespace

void NurbsPatch::basis(Vec2 x, std::span<Jet> out) const {
  assert(out.size() == size());
  std::fill(out.begin(), out.end(), Jet(0.0));
  const auto l = rational_local(grid_, weights_, x);
  for (int a = 0; a <= grid_.p(); ++a)
    for (int b = 0; b <= grid_.q(); ++b)
      out[(l.i0 + a) * grid_.nv() + l.j0 + b] = l.phi[a * (grid_.q() + 1) + b];
}

SurfaceJet NurbsPatch::evaluate(Vec2 x) const {
  const auto l = rational_local(grid_, weights_, x);
  return grid_.combine(l, points_);
}

void NurbsPatch::influence(std::size_t k, std::span<const Vec2> xs, std::span<Jet> out) const {
  assert(k < size() && xs.size() == out.size());
  const int i = static_cast<int>(k / grid_.nv()), j = static_cast<int>(k % grid_.nv());
  for (std::size_t s = 0; s < xs.size(); ++s) {
    out[s] = Jet(0.0);
    if (!grid_.touches(k, xs[s])) continue;
    const auto l = rational_local(grid_, weights_, xs[s]);
    out[s] = l.phi[(i - l.i0) * (grid_.q() + 1) + (j - l.j0)];
  }
}

Vec3 NurbsPatch::boundary_point(int side, double t) const {
  return spline_boundary_point(grid_, points_, weights_, side, t);
}

NurbsPatch NurbsPatch::inserted_u(double t) const {
  const std::size_t nu = grid_.nu(), nv = grid_.nv();
  std::vector<double> U;
  std::vector<Vec3> pts((nu + 1) * nv);
  std::vector<double> w((nu + 1) * nv);
  for (std::size_t j = 0; j < nv; ++j) {
    U = grid_.knots_u();
    std::vector<glm::dvec4> row;
    for (std::size_t i = 0; i < nu; ++i) {
      const double wi = weights_[i * nv + j];
      row.emplace_back(wi * points_[i * nv + j], wi);
    }
    insert_knot(grid_.p(), U, row, t);
    for (std::size_t i = 0; i <= nu; ++i) {
      pts[i * nv + j] = Vec3(row[i]) / row[i].w;
      w[i * nv + j] = row[i].w;
    }
  }
  return NurbsPatch(grid_.p(), grid_.q(), U, grid_.knots_v(), nu + 1, nv, std::move(pts),
                    std::move(w));
}

}  // namespace pl
