#include "core/param/mean_value.hpp"

#include <cassert>
#include <cmath>
#include <stdexcept>
#include <string>

namespace pl {

namespace {

constexpr int kMaxVertices = MeanValueParameters::kMaxSides;

// A function linear in x, its gradient per sample.
template <class T>
struct LinearOf {
  T f, fu, fv;
};

// a * b for linear a and b: a quadratic.
template <class T>
PATCHLAB_LANES_INLINE JetOf<T> linear_product(const LinearOf<T>& a, const LinearOf<T>& b) {
  return {a.f * b.f,       a.fu * b.f + a.f * b.fu,   a.fv * b.f + a.f * b.fv,
          2 * a.fu * b.fu, a.fu * b.fv + a.fv * b.fu, 2 * a.fv * b.fv};
}

}  // namespace

// The one body of the scalar and the lane forms (T = double or a lane type): the same operations
// in the same order, so a lane gives the scalar path's numbers bit for bit. With d_i = p_i - x
// (linear in x): r_i = |d_i|, the signed area A_i = cross(d_i, d_i+1) (linear: the x cross x
// terms cancel) and D_i = dot(d_i, d_i+1) (quadratic), their jets written out.
template <class T>
PATCHLAB_LANES_INLINE void mean_value_at(std::span<const Vec2> poly, const T& u, const T& v,
                                         JetOf<T>* out) {
  using J = JetOf<T>;
  constexpr int W = lane_count<T>;
  const int n = static_cast<int>(poly.size());
  assert(n >= 3 && n <= kMaxVertices);
  const T z{};
  const auto next = [n](int i) { return i + 1 == n ? 0 : i + 1; };
  Scratch<T, kMaxVertices> dx, dy, ir;
  Scratch<J, kMaxVertices> r, t;
  Scratch<LinearOf<T>, kMaxVertices> area;
  for (int i = 0; i < n; ++i) {
    dx[i] = poly[i].x - u, dy[i] = poly[i].y - v;
    T root = dx[i] * dx[i] + dy[i] * dy[i];
    for (int b = 0; b < W; ++b) set_lane_value(root, b, std::sqrt(lane_value(root, b)));
    ir[i] = 1.0 / root;
    const T ir3 = ir[i] * ir[i] * ir[i];
    r[i] = {root,
            -dx[i] * ir[i],
            -dy[i] * ir[i],
            dy[i] * dy[i] * ir3,
            -dx[i] * dy[i] * ir3,
            dx[i] * dx[i] * ir3};
  }
  // The segment nearest to x among those x projects inside (none: -1): its weight term is the one
  // that blows up at the boundary, so every weight is multiplied by its signed area A_k, turning
  // A_k tan(alpha_k / 2) into r_k r_k+1 - D_k (as A^2 = (r r - D)(r r + D)).
  T best = z + INFINITY, nearest = z - 1;
  for (int i = 0; i < n; ++i) {
    const Vec2 a = poly[i], ab = poly[next(i)] - a;
    const T s = (-dx[i] * ab.x - dy[i] * ab.y) / glm::dot(ab, ab);
    const T ex = dx[i] + s * ab.x, ey = dy[i] + s * ab.y;  // (a + s ab) - x
    const T d2 = ex * ex + ey * ey;
    const auto take = (s > 0) & (s < 1) & (d2 < best);
    best = take ? d2 : best;
    nearest = take ? z + i : nearest;
  }
  int k[W];
  for (int b = 0; b < W; ++b) k[b] = static_cast<int>(lane_value(nearest, b));
  for (int i = 0; i < n; ++i) {
    const int j = next(i);
    area[i] = {dx[i] * dy[j] - dy[i] * dx[j], z + (poly[i].y - poly[j].y),
               z + (poly[j].x - poly[i].x)};
  }
  // Every weight times A_k (times 1 where x projects inside no segment).
  LinearOf<T> area_k{z + 1, z, z};
  for (int b = 0; b < W; ++b)
    if (k[b] >= 0) {
      set_lane_value(area_k.f, b, lane_value(area[k[b]].f, b));
      set_lane_value(area_k.fu, b, lane_value(area[k[b]].fu, b));
      set_lane_value(area_k.fv, b, lane_value(area[k[b]].fv, b));
    }
  // tan(alpha_i / 2) = A_i / (r_i r_i+1 + D_i): finite wherever x is off segment i, including
  // on the segment's line extension (where the (r r - D) / A form is 0/0).
  for (int i = 0; i < n; ++i) {
    const int j = next(i);
    const J rr = product(r[i], r[j]);
    const J dot = {
        dx[i] * dx[j] + dy[i] * dy[j], -(dx[i] + dx[j]), -(dy[i] + dy[j]), z + 2, z, z + 2};
    t[i] = product(linear_product(area_k, area[i]), reciprocal(sum(rr, dot)));
    for (int b = 0; b < W; ++b)
      if (k[b] == i) set_lane(t[i], b, lane(difference(rr, dot), b));
  }
  J total = constant_jet<T>(0.0);
  for (int i = 0; i < n; ++i) {
    const T d1 = -ir[i] * ir[i];  // 1 / r_i by the chain rule
    out[i] = product(sum(t[i == 0 ? n - 1 : i - 1], t[i]), chain(r[i], ir[i], d1, -2 * d1 * ir[i]));
    add_to(total, out[i]);
  }
  const J inv = reciprocal(total);
  for (int i = 0; i < n; ++i) out[i] = product(out[i], inv);
}

void mean_value_coordinates(std::span<const Vec2> poly, Vec2 x, std::span<Jet> out) {
  assert(out.size() == poly.size());
  mean_value_at<double>(poly, x.x, x.y, out.data());
}

MeanValueParameters::MeanValueParameters(std::vector<Vec2> vertices)
    : Parameterization(std::move(vertices)) {
  if (sides() < 3 || sides() > kMaxSides)
    throw std::invalid_argument("mean value parameters need 3 to " + std::to_string(kMaxSides) +
                                " vertices, got " + std::to_string(sides()));
}

void MeanValueParameters::evaluate(Vec2 x, std::span<Jet> lambda, std::span<Jet> s,
                                   std::span<Jet> h, SideMask sides) const {
  const int n = this->sides();
  Scratch<Jet, kMaxSides> own;
  const std::span<Jet> lam = lambda.empty() ? std::span<Jet>(own.data(), n) : lambda;
  mean_value_coordinates(vertices_, x, lam);
  if (!h.empty()) sums_off_side<kMaxSides + 1>(n, lam.data(), h.data(), sides, Jet(0.0));
  if (!s.empty())
    for (int i = 0; i < n; ++i)
      if (sides >> i & 1u) s[i] = lam[i] / (lam[wrap(i - 1)] + lam[i]);
}

template <class T>
PATCHLAB_LANES_INLINE void MeanValueParameters::sample_lanes(const T& u, const T& v,
                                                             JetOf<T>* lambda, JetOf<T>* h) const {
  mean_value_at(vertices_, u, v, lambda);
  sums_off_side<kMaxSides + 1>(sides(), lambda, h, kAllSides, constant_jet<T>(0.0));
}

PATCHLAB_LANES_CLONES
void MeanValueParameters::evaluate_lanes(const Lane& u, const Lane& v, JetLanes* lambda,
                                         JetLanes* h) const {
  sample_lanes(u, v, lambda, h);
}

PATCHLAB_LANES_WIDE
void MeanValueParameters::evaluate_lanes(const WideLane& u, const WideLane& v, WideJetLanes* lambda,
                                         WideJetLanes* h) const {
  sample_lanes(u, v, lambda, h);
}

}  // namespace pl
