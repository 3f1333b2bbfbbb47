#include "core/patch/spline_grid.hpp"

namespace pl {

SplineGrid::SplineGrid(int p, int q, std::vector<double> ku, std::vector<double> kv, std::size_t nu,
                       std::size_t nv)
    : p_(p), q_(q), ku_(std::move(ku)), kv_(std::move(kv)), nu_(nu), nv_(nv) {
  validate_knots(p_, ku_, nu_);
  validate_knots(q_, kv_, nv_);
}

SplineGrid::Local SplineGrid::local(Vec2 x) const {
  const SplineBasis bu = spline_basis(p_, ku_, nu_, u_of(x.x));
  const SplineBasis bv = spline_basis(q_, kv_, nv_, v_of(x.y));
  const double su = ku_[nu_] - ku_[p_], sv = kv_[nv_] - kv_[q_];  // d(u)/dx, d(v)/dy
  Local l;
  l.i0 = bu.span - p_;
  l.j0 = bv.span - q_;
  for (int a = 0; a <= p_; ++a)
    for (int b = 0; b <= q_; ++b)
      l.phi[a * (q_ + 1) + b] = Jet(bu.d0[a] * bv.d0[b], su * bu.d1[a] * bv.d0[b],
                                    sv * bu.d0[a] * bv.d1[b], su * su * bu.d2[a] * bv.d0[b],
                                    su * sv * bu.d1[a] * bv.d1[b], sv * sv * bu.d0[a] * bv.d2[b]);
  return l;
}

bool SplineGrid::touches(std::size_t k, Vec2 x) const {
  const int i = static_cast<int>(k / nv_), j = static_cast<int>(k % nv_);
  const int su = find_span(p_, ku_, nu_, u_of(x.x)), sv = find_span(q_, kv_, nv_, v_of(x.y));
  return i >= su - p_ && i <= su && j >= sv - q_ && j <= sv;
}

SurfaceJet SplineGrid::combine(const Local& l, const std::vector<Vec3>& points) const {
  // Summed relative to the local point of largest weight (the basis is a partition of unity):
  // where only coinciding points carry weight, such as on a sphere's pole row, the derivatives
  // are then exactly zero instead of rounding noise that would pass for a regular point.
  const int m = (p() + 1) * (q() + 1);
  int best = 0;
  for (int a = 1; a < m; ++a)
    if (l.phi[a].f > l.phi[best].f) best = a;
  const Vec3 ref = points[(l.i0 + best / (q() + 1)) * nv() + l.j0 + best % (q() + 1)];
  SurfaceJet s;
  s.p = ref;
  for (int a = 0; a <= p(); ++a)
    for (int b = 0; b <= q(); ++b)
      add_scaled(s, l.phi[a * (q() + 1) + b], points[(l.i0 + a) * nv() + l.j0 + b] - ref);
  return s;
}

}  // namespace pl
