#include "core/patch/gap_fill_patch.hpp"

#include <cassert>
#include <cmath>
#include <stdexcept>

#include "core/curve/hermite_curve.hpp"
#include "core/math/bspline_basis.hpp"
#include "core/math/cubic_bases.hpp"

namespace pl {

namespace {
std::vector<Vec3> all_points(const BSplinePatch& q, const BSplinePatch& r) {
  std::vector<Vec3> p = q.control_points();
  p.insert(p.end(), r.control_points().begin(), r.control_points().end());
  return p;
}

bool clamped_end(const std::vector<double>& U, int p, bool at_start) {
  const std::size_t m = U.size();
  for (int k = 1; k <= p; ++k)
    if (at_start ? U[k] != U[0] : U[m - 1 - k] != U[m - 1]) return false;
  return true;
}

// |f(y)| as a jet in the y direction of the domain (scale = dv/dy) from a curve's point.
Jet norm_jet(const CurvePoint& c, double scale) {
  Jet s(0.0);
  for (int i = 0; i < 3; ++i) {
    const Jet x(c.p[i], 0, scale * c.d1[i], 0, 0, scale * scale * c.d2[i]);
    s += x * x;
  }
  return sqrt(s);
}
}  // namespace

GapFillPatch::GapFillPatch(BSplinePatch q, BSplinePatch r)
    : PatchType(all_points(q, r)),
      q_(std::make_shared<BSplinePatch>(std::move(q))),
      r_(std::make_shared<BSplinePatch>(std::move(r))) {
  const SplineGrid &gq = q_->grid(), &gr = r_->grid();
  const double a = gq.v_of(0), b = gq.v_of(1);
  if (std::fabs(gr.v_of(0) - a) > 1e-12 * (1 + std::fabs(a)) ||
      std::fabs(gr.v_of(1) - b) > 1e-12 * (1 + std::fabs(b)))
    throw std::invalid_argument("the two patches must have the same v range [a, b]");
  if (!clamped_end(gq.knots_u(), gq.p(), false) || !clamped_end(gr.knots_u(), gr.p(), true))
    throw std::invalid_argument("q must be clamped at its last u knot and r at its first");
  const auto& U = gq.knots_u();
  const std::size_t n = gq.nu();
  kq_ = gq.p() / (U[n + gq.p() - 1] - U[n - 1]);
  kr_ = gr.p() / (gr.knots_u()[gr.p() + 1] - gr.knots_u()[1]);
  std::vector<Vec3> qe, qc, re, rc;
  for (std::size_t j = 0; j < gq.nv(); ++j) {
    qe.push_back(q_->control_point((n - 1) * gq.nv() + j));
    qc.push_back(kq_ * (qe.back() - q_->control_point((n - 2) * gq.nv() + j)));
  }
  for (std::size_t j = 0; j < gr.nv(); ++j) {
    re.push_back(r_->control_point(j));
    rc.push_back(kr_ * (r_->control_point(gr.nv() + j) - re.back()));
  }
  q_end_ = std::make_shared<BSplineCurve>(gq.q(), gq.knots_v(), qe);
  q_cross_ = std::make_shared<BSplineCurve>(gq.q(), gq.knots_v(), qc);
  r_end_ = std::make_shared<BSplineCurve>(gr.q(), gr.knots_v(), re);
  r_cross_ = std::make_shared<BSplineCurve>(gr.q(), gr.knots_v(), rc);
  // The scale functions divide by |q_u|, |r_u| and take sqrt of d^2: all must stay away from 0.
  for (int k = 0; k <= 400; ++k) {
    const double v = a + (b - a) * k / 400.0;
    const double d = glm::length(q_end_->evaluate(v).p - r_end_->evaluate(v).p);
    if (!(d > 1e-9 * (1 + glm::length(q_end_->evaluate(v).p))))
      throw std::invalid_argument("the gap closes at v = " + std::to_string(v) +
                                  ": nothing to fill");
    if (!(glm::length(q_cross_->evaluate(v).p) > 0) || !(glm::length(r_cross_->evaluate(v).p) > 0))
      throw std::invalid_argument("a cross-boundary derivative vanishes at v = " +
                                  std::to_string(v));
  }
}

void GapFillPatch::set_control_point(std::size_t k, const Vec3& p) {
  points_.at(k) = p;
  const std::size_t nq = q_->size();
  if (k < nq) {
    q_ = std::make_shared<BSplinePatch>(*q_);
    q_->set_control_point(k, p);
  } else {
    r_ = std::make_shared<BSplinePatch>(*r_);
    r_->set_control_point(k - nq, p);
  }
}

ControlPointKind GapFillPatch::kind(std::size_t k) const {
  const std::size_t nq = q_->size();
  return k < nq ? q_->kind(k) : r_->kind(k - nq);
}

double GapFillPatch::gap_width(double y) const {
  const double v = q_->grid().v_of(y);
  return glm::length(q_end_->evaluate(v).p - r_end_->evaluate(v).p);
}

void GapFillPatch::fill_basis(Vec2 local, std::span<Jet> out) const {
  for (Jet& j : out) j = Jet(0.0);
  const SplineGrid &gq = q_->grid(), &gr = r_->grid();
  const double v = gq.v_of(local.y), L = gq.v_of(1) - gq.v_of(0);  // dv/dy
  // Frozen scale functions c1 = d / |q_u|, g1 = d / |r_u| as jets in y.
  const CurvePoint qe = q_end_->evaluate(v), re = r_end_->evaluate(v);
  const CurvePoint gap{qe.p - re.p, qe.d1 - re.d1, qe.d2 - re.d2};
  const Jet d = norm_jet(gap, L);
  const Jet c1 = d / norm_jet(q_cross_->evaluate(v), L),
            g1 = d / norm_jet(r_cross_->evaluate(v), L);
  const CubicBasis h = hermite_basis(local.x);
  const auto hj = [&](int k) { return Jet(h.d0[k], h.d1[k], 0, h.d2[k], 0, 0); };
  const Jet a0 = hj(0), a1 = hj(1), b0 = hj(2), b1 = hj(3);
  // q(d, v) = sum_j N_j(v) P_{n-1,j};  q_u(d, v) = sum_j N_j(v) kq (P_{n-1,j} - P_{n-2,j}).
  const SplineBasis nq = spline_basis(gq.q(), gq.knots_v(), gq.nv(), v);
  for (int t = 0; t <= gq.q(); ++t) {
    const std::size_t j = nq.span - gq.q() + t;
    const Jet N(nq.d0[t], 0, L * nq.d1[t], 0, 0, L * L * nq.d2[t]);
    out[(gq.nu() - 1) * gq.nv() + j] += N * (a0 + kq_ * b0 * c1);
    out[(gq.nu() - 2) * gq.nv() + j] -= N * (kq_ * b0 * c1);
  }
  const std::size_t off = q_->size();
  const SplineBasis nr = spline_basis(gr.q(), gr.knots_v(), gr.nv(), gr.v_of(local.y));
  const double Lr = gr.v_of(1) - gr.v_of(0);
  for (int t = 0; t <= gr.q(); ++t) {
    const std::size_t j = nr.span - gr.q() + t;
    const Jet N(nr.d0[t], 0, Lr * nr.d1[t], 0, 0, Lr * Lr * nr.d2[t]);
    out[off + j] += N * (a1 - kr_ * b1 * g1);
    out[off + gr.nv() + j] += N * (kr_ * b1 * g1);
  }
}

namespace {
struct Piece {
  int index;
  Vec2 local;
};
Piece piece_of(Vec2 x) {
  const int i = x.x < 1.0 / 3 ? 0 : x.x < 2.0 / 3 ? 1 : 2;
  return {i, {3 * x.x - i, x.y}};
}
}  // namespace

void GapFillPatch::basis(Vec2 x, std::span<Jet> out) const {
  assert(out.size() == size());
  const Piece pc = piece_of(x);
  const std::size_t nq = q_->size();
  if (pc.index == 1) {
    fill_basis(pc.local, out);
  } else {
    for (Jet& j : out) j = Jet(0.0);
    const BSplinePatch& p = pc.index == 0 ? *q_ : *r_;
    p.basis(pc.local, out.subspan(pc.index == 0 ? 0 : nq, p.size()));
  }
  for (Jet& j : out) j.fu *= 3, j.fuu *= 9, j.fuv *= 3;  // local u = 3x - piece
}

SurfaceJet GapFillPatch::piece_jet(int piece, Vec2 local) const {
  if (piece == 0) return q_->evaluate(local);
  if (piece == 2) return r_->evaluate(local);
  std::vector<Jet> phi(size());
  fill_basis(local, phi);
  return combine(points_, phi);
}

std::vector<BezierCurve> GapFillPatch::boundary_curves() const {
  const auto qs = q_->boundary_curves(), rs = r_->boundary_curves();
  const auto P = [&](int piece, double u, double y) { return piece_jet(piece, {u, y}).p; };
  return {BezierCurve({P(0, 0, 0), P(0, 1, 0), P(2, 0, 0), P(2, 1, 0)}), rs[1],
          BezierCurve({P(2, 1, 1), P(2, 0, 1), P(0, 1, 1), P(0, 0, 1)}), qs[3]};
}

Vec3 GapFillPatch::boundary_point(int side, double t) const {
  if (side == 1) return r_->boundary_point(1, t);
  if (side == 3) return q_->boundary_point(3, t);
  // Sides 0 (y = 0, x = t) and 2 (y = 1, x = 1 - t) cross q, the fill and r.
  const double x = side == 0 ? t : 1.0 - t, y = side == 0 ? 0.0 : 1.0;
  const auto along = [&](double local) { return side == 0 ? local : 1.0 - local; };
  if (x < 1.0 / 3) return q_->boundary_point(side, along(3 * x));
  if (x >= 2.0 / 3) return r_->boundary_point(side, along(3 * x - 2));
  const SplineGrid &gq = q_->grid(), &gr = r_->grid();
  // The curves q(d, v), q_u(d, v), r(e, v), r_u(e, v) of the current points (q clamped at d,
  // r at e, so the end columns and their differences are the curves' control points).
  std::vector<Vec3> qe, qc, re, rc;
  for (std::size_t j = 0; j < gq.nv(); ++j) {
    qe.push_back(q_->control_point((gq.nu() - 1) * gq.nv() + j));
    qc.push_back(kq_ * (qe.back() - q_->control_point((gq.nu() - 2) * gq.nv() + j)));
  }
  for (std::size_t j = 0; j < gr.nv(); ++j) {
    re.push_back(r_->control_point(j));
    rc.push_back(kr_ * (r_->control_point(gr.nv() + j) - re.back()));
  }
  const double vq = gq.v_of(y), vr = gr.v_of(y);
  // The frozen scale functions c1 = d / |q_u|, g1 = d / |r_u| (construction-time curves).
  const double d = glm::length(q_end_->evaluate(vq).p - r_end_->evaluate(vr).p);
  const double c1 = d / glm::length(q_cross_->evaluate(vq).p),
               g1 = d / glm::length(r_cross_->evaluate(vr).p);
  const HermiteCurve fill(BSplineCurve(gq.q(), gq.knots_v(), qe).evaluate(vq).p,
                          BSplineCurve(gr.q(), gr.knots_v(), re).evaluate(vr).p,
                          c1 * BSplineCurve(gq.q(), gq.knots_v(), qc).evaluate(vq).p,
                          g1 * BSplineCurve(gr.q(), gr.knots_v(), rc).evaluate(vr).p);
  return fill.evaluate(3 * x - 1).p;
}

}  // namespace pl
