#include "core/patch/pair_join_patch.hpp"

#include <cassert>
#include <stdexcept>

#include "core/math/bernstein.hpp"

namespace pl {

namespace {
constexpr int kFinalDegree = 5;

// Product of a scalar polynomial and a curve, both in Bernstein form, elevated to degree 5.
BezierCurve times(const std::vector<double>& f, const BezierCurve& g, const char* what) {
  const int m = static_cast<int>(f.size()) - 1, n = g.degree();
  if (m + n > kFinalDegree)
    throw std::invalid_argument(std::string("junction term ") + what + " has degree " +
                                std::to_string(m + n) + " > 5");
  std::vector<Vec3> h(m + n + 1, Vec3(0));
  for (int i = 0; i <= m; ++i)
    for (int j = 0; j <= n; ++j)
      h[i + j] +=
          binomial(m, i) * binomial(n, j) / binomial(m + n, i + j) * f[i] * g.control_points()[j];
  return BezierCurve(h).elevated_to(kFinalDegree);
}

std::vector<double> times(const std::vector<double>& f, const std::vector<double>& g) {
  const int m = static_cast<int>(f.size()) - 1, n = static_cast<int>(g.size()) - 1;
  std::vector<double> h(m + n + 1, 0.0);
  for (int i = 0; i <= m; ++i)
    for (int j = 0; j <= n; ++j)
      h[i + j] += binomial(m, i) * binomial(n, j) / binomial(m + n, i + j) * f[i] * g[j];
  return h;
}

void check_function(const std::vector<double>& f, const char* name, bool required) {
  if (f.empty()) {
    if (required)
      throw std::invalid_argument(std::string("junction function ") + name + " is missing");
    return;
  }
  for (double x : f)
    if (!std::isfinite(x))
      throw std::invalid_argument(std::string("junction function ") + name + " is not finite");
}
}  // namespace

PairJoinPatch::PairJoinPatch(int order, int du, int dv, std::vector<Vec3> aux, JunctionFunctions a,
                             JunctionFunctions b)
    : PatchType(std::move(aux)),
      order_(order),
      du_(du),
      dv_(dv),
      junction_{std::move(a), std::move(b)} {
  if (order_ != 1 && order_ != 2) throw std::invalid_argument("order must be 1 (G1) or 2 (G2)");
  if (du_ < 1 || du_ > kFinalDegree)
    throw std::invalid_argument("auxiliary degree in s must be 1..5");
  if (dv_ < order_ || dv_ > 5)
    throw std::invalid_argument("auxiliary degree in t must be between the order and 5");
  if (points_.size() != static_cast<std::size_t>((du_ + 1) * (dv_ + 1)))
    throw std::invalid_argument("the auxiliary patch needs " +
                                std::to_string((du_ + 1) * (dv_ + 1)) + " points");
  for (int w = 0; w < 2; ++w) {
    const JunctionFunctions& j = junction_[w];
    check_function(j.b1, "b1", true);
    check_function(j.c1, "c1", true);
    check_function(j.b2, "b2", order_ == 2);
    check_function(j.c2, "c2", order_ == 2);
    // A positive (negative) Bernstein polygon keeps c1 of one sign on [0,1]: no cusp.
    for (double c : j.c1)
      if (w == 0 ? !(c > 0) : !(c < 0))
        throw std::invalid_argument(w == 0 ? "c1 of patch a must have positive coefficients"
                                           : "c1 of patch b must have negative coefficients");
  }
  // The construction is linear in the auxiliary points: record it on unit vectors once.
  for (int w = 0; w < 2; ++w) {
    std::vector<Vec3> unit(size(), Vec3(0));
    const std::size_t finals = (kFinalDegree + 1) * (order_ + 1);
    map_[w].assign(finals * size(), 0.0);
    for (std::size_t k = 0; k < size(); ++k) {
      unit[k] = Vec3(1, 0, 0);
      const std::vector<Vec3> f = construct(unit, w);
      for (std::size_t l = 0; l < finals; ++l) map_[w][l * size() + k] = f[l].x;
      unit[k] = Vec3(0);
    }
  }
  rebuild();
}

std::vector<Vec3> PairJoinPatch::construct(const std::vector<Vec3>& a, int which) const {
  const JunctionFunctions& J = junction_[which];
  auto row = [&](int j) {
    std::vector<Vec3> r;
    for (int i = 0; i <= du_; ++i) r.push_back(a[i * (dv_ + 1) + j]);
    return BezierCurve(r);
  };
  const BezierCurve p0 = row(0), p1 = row(1);
  const BezierCurve ps = p0.derivative();
  std::vector<Vec3> tv;
  for (int i = 0; i <= du_; ++i)
    tv.push_back(double(dv_) * (p1.control_points()[i] - p0.control_points()[i]));
  const BezierCurve pt(tv);
  const int n = order_;
  std::vector<Vec3> out((kFinalDegree + 1) * (n + 1));
  const auto P0 = p0.elevated_to(kFinalDegree).control_points();
  const BezierCurve d1a = times(J.b1, ps, "b1 p_s"), d1b = times(J.c1, pt, "c1 p_t");
  std::vector<Vec3> P1(kFinalDegree + 1);
  for (int i = 0; i <= kFinalDegree; ++i)
    P1[i] = P0[i] + (d1a.control_points()[i] + d1b.control_points()[i]) / double(n);
  for (int i = 0; i <= kFinalDegree; ++i) out[i * (n + 1)] = P0[i], out[i * (n + 1) + 1] = P1[i];
  if (n == 2) {
    std::vector<Vec3> tt;
    const BezierCurve p2 = row(2);
    for (int i = 0; i <= du_; ++i)
      tt.push_back(
          double(dv_ * (dv_ - 1)) *
          (p2.control_points()[i] - 2.0 * p1.control_points()[i] + p0.control_points()[i]));
    const BezierCurve terms[5] = {times(J.b2, ps, "b2 p_s"), times(J.c2, pt, "c2 p_t"),
                                  times(times(J.b1, J.b1), ps.derivative(), "b1^2 p_ss"),
                                  times(times(J.b1, J.c1), pt.derivative(), "b1 c1 p_st"),
                                  times(times(J.c1, J.c1), BezierCurve(tt), "c1^2 p_tt")};
    for (int i = 0; i <= kFinalDegree; ++i) {
      Vec3 d2 = terms[0].control_points()[i] + terms[1].control_points()[i] +
                terms[2].control_points()[i] + 2.0 * terms[3].control_points()[i] +
                terms[4].control_points()[i];
      // p*_vv(u, 0) = n (n - 1) (P2 - 2 P1 + P0) with n = 2.
      out[i * 3 + 2] = d2 / 2.0 + 2.0 * P1[i] - P0[i];
    }
  }
  return out;
}

void PairJoinPatch::rebuild() {
  for (int w = 0; w < 2; ++w) {
    const std::size_t finals = map_[w].size() / size();
    std::vector<Vec3> f(finals, Vec3(0));
    for (std::size_t l = 0; l < finals; ++l)
      for (std::size_t k = 0; k < size(); ++k) f[l] += map_[w][l * size() + k] * points_[k];
    final_[w] = std::make_shared<BezierPatch>(kFinalDegree, order_, std::move(f));
  }
}

void PairJoinPatch::set_control_point(std::size_t k, const Vec3& p) {
  points_.at(k) = p;
  rebuild();
}

ControlPointKind PairJoinPatch::kind(std::size_t k) const {
  return static_cast<int>(k) % (dv_ + 1) == 0 ? ControlPointKind::Boundary
                                              : ControlPointKind::Inner;
}

namespace {
struct Half {
  int which;  // 0: A, 1: B
  Vec2 local;
  double dv;  // d(local v)/dv
};
Half half_of(Vec2 x) {
  if (x.y >= 0.5) return {0, {x.x, 2 * x.y - 1}, 2.0};
  return {1, {x.x, 1 - 2 * x.y}, -2.0};
}
}  // namespace

SurfaceJet PairJoinPatch::evaluate(Vec2 x) const {
  const Half h = half_of(x);
  SurfaceJet s = final_[h.which]->evaluate(h.local);
  s.sv *= h.dv, s.suv *= h.dv, s.svv *= h.dv * h.dv;
  return s;
}

void PairJoinPatch::basis(Vec2 x, std::span<Jet> out) const {
  assert(out.size() == size());
  const Half h = half_of(x);
  const BezierPatch& f = *final_[h.which];
  std::vector<Jet> b(f.size());
  f.basis(h.local, b);
  for (Jet& j : out) j = Jet(0.0);
  for (std::size_t l = 0; l < b.size(); ++l) {
    const Jet w(b[l].f, b[l].fu, h.dv * b[l].fv, b[l].fuu, h.dv * b[l].fuv, h.dv * h.dv * b[l].fvv);
    for (std::size_t k = 0; k < size(); ++k)
      if (const double m = map_[h.which][l * size() + k]; m != 0) out[k] += w * m;
  }
}

std::vector<BezierCurve> PairJoinPatch::boundary_curves() const {
  const BezierPatch &A = *final_[0], &B = *final_[1];
  const int n = order_, d = kFinalDegree;
  std::vector<Vec3> s0, s2;
  for (int i = 0; i <= d; ++i) s0.push_back(B.at(i, n)), s2.push_back(A.at(d - i, n));
  return {BezierCurve(s0), BezierCurve({B.at(d, n), A.at(d, 0), A.at(d, n)}), BezierCurve(s2),
          BezierCurve({A.at(0, n), A.at(0, 0), B.at(0, n)})};
}

Vec3 PairJoinPatch::boundary_point(int side, double t) const {
  if (side == 0 || side == 2) return boundary_curves().at(side).point(t);  // one Bézier row
  const int n = order_, i = side == 1 ? kFinalDegree : 0;
  const double v = side == 1 ? t : 1.0 - t;
  // The end column of A (v >= 1/2, A(u, 2v - 1)) or B (v < 1/2, B(u, 1 - 2v)) as a curve.
  const BezierPatch& P = v >= 0.5 ? *final_[0] : *final_[1];
  std::vector<Vec3> column;
  for (int j = 0; j <= n; ++j) column.push_back(P.at(i, j));
  return BezierCurve(column).point(v >= 0.5 ? 2 * v - 1 : 1 - 2 * v);
}

}  // namespace pl
