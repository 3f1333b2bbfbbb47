#include "core/patch/bezier_patch.hpp"

#include <array>
#include <cassert>
#include <stdexcept>

#include "core/math/bernstein.hpp"

namespace pl {

namespace {
constexpr int kMaxDegree = 30;
struct Bernstein3 {  // values and derivatives of all polynomials of one degree at one t
  std::array<double, kMaxDegree + 1> d0, d1, d2;
  Bernstein3(int n, double t) { bernstein_all_d2(n, t, d0, d1, d2); }
};
}  // namespace

BezierPatch::BezierPatch(int m, int n, std::vector<Vec3> points)
    : UnitSquarePatch(std::move(points)), m_(m), n_(n) {
  if (m < 1 || n < 1 || m > kMaxDegree || n > kMaxDegree)
    throw std::invalid_argument("Bézier patch degrees must be between 1 and 30");
  if (points_.size() != static_cast<std::size_t>((m + 1) * (n + 1)))
    throw std::invalid_argument("a Bézier patch of degree [" + std::to_string(m) + ", " +
                                std::to_string(n) + "] needs " + std::to_string((m + 1) * (n + 1)) +
                                " points, got " + std::to_string(points_.size()));
}

ControlPointKind BezierPatch::kind(std::size_t k) const {
  const int i = static_cast<int>(k) / (n_ + 1), j = static_cast<int>(k) % (n_ + 1);
  return (i == 0 || i == m_ || j == 0 || j == n_) ? ControlPointKind::Boundary
                                                  : ControlPointKind::Inner;
}

void BezierPatch::basis(Vec2 x, std::span<Jet> out) const {
  assert(out.size() == size());
  const Bernstein3 bu(m_, x.x), bv(n_, x.y);
  for (int i = 0; i <= m_; ++i)
    for (int j = 0; j <= n_; ++j)
      out[i * (n_ + 1) + j] = Jet(bu.d0[i] * bv.d0[j], bu.d1[i] * bv.d0[j], bu.d0[i] * bv.d1[j],
                                  bu.d2[i] * bv.d0[j], bu.d1[i] * bv.d1[j], bu.d0[i] * bv.d2[j]);
}

SurfaceJet BezierPatch::evaluate(Vec2 x) const {
  // Contract over j first (three v-derivative orders), then over i: O(m n) instead of a full
  // basis evaluation.
  const Bernstein3 bu(m_, x.x), bv(n_, x.y);
  SurfaceJet s;
  for (int i = 0; i <= m_; ++i) {
    Vec3 r0(0), r1(0), r2(0);
    const Vec3* row = &points_[i * (n_ + 1)];
    for (int j = 0; j <= n_; ++j) {
      r0 += bv.d0[j] * row[j];
      r1 += bv.d1[j] * row[j];
      r2 += bv.d2[j] * row[j];
    }
    s.p += bu.d0[i] * r0;
    s.su += bu.d1[i] * r0;
    s.sv += bu.d0[i] * r1;
    s.suu += bu.d2[i] * r0;
    s.suv += bu.d1[i] * r1;
    s.svv += bu.d0[i] * r2;
  }
  return s;
}

void BezierPatch::influence(std::size_t k, std::span<const Vec2> xs, std::span<Jet> out) const {
  assert(k < size() && xs.size() == out.size());
  const int i = static_cast<int>(k) / (n_ + 1), j = static_cast<int>(k) % (n_ + 1);
  for (std::size_t s = 0; s < xs.size(); ++s) {
    const Jet u = bernstein(m_, i, Jet::u(xs[s].x));
    const Jet v = bernstein(n_, j, Jet::v(xs[s].y));
    out[s] = u * v;
  }
}

std::vector<BezierCurve> BezierPatch::boundary_curves() const {
  std::vector<Vec3> s0, s1, s2, s3;
  for (int i = 0; i <= m_; ++i) s0.push_back(at(i, 0));
  for (int j = 0; j <= n_; ++j) s1.push_back(at(m_, j));
  for (int i = m_; i >= 0; --i) s2.push_back(at(i, n_));
  for (int j = n_; j >= 0; --j) s3.push_back(at(0, j));
  return {BezierCurve(s0), BezierCurve(s1), BezierCurve(s2), BezierCurve(s3)};
}

}  // namespace pl
