#include "core/patch/gb_ribbon_patch.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "core/math/bernstein.hpp"
#include "core/math/scratch.hpp"
#include "core/param/mean_value.hpp"

namespace pl {

namespace {

// Where |D| / |grad D| (about the distance to a side) is below this, x is on that side.
constexpr double kOnSide = 1e-12;

// binomial(n, k) for n <= kMaxDegree (the values binomial() gives, which are exact here) without
// its loop of divisions: evaluate() needs d + 1 + l of them per ribbon and sample.
double binomial_of(int n, int k) {
  constexpr int N = GBRibbonPatch::kMaxDegree + 1;
  static const auto table = [] {
    std::array<std::array<double, N>, N> t{};
    for (int a = 0; a < N; ++a)
      for (int b = 0; b <= a; ++b) t[a][b] = binomial(a, b);
    return t;
  }();
  return n < N ? table[n][k] : binomial(n, k);
}

// a^0 .. a^top (top <= kCap - 1 here), each by repeated multiplication from 1 like pow(a, k),
// so a table entry is bitwise the value pow() gives. One table per jet and sample replaces the
// pow() calls of every blend term (which recomputed the same powers term after term).
// Exponents past the table (degrees beyond the format's limits) continue the multiplication, so
// the values stay those of pow() for any degree.
class Powers {
 public:
  static constexpr int kCap = 2 * GBRibbonPatch::kMaxLayers + 2;
  static_assert(kCap > GBRibbonPatch::kMaxDegree);

  void build(const Jet& a, int top) {
    base_ = a;
    top_ = std::min(std::max(top, 0), kCap - 1);
    p_[0] = Jet(1.0);
    for (int k = 1; k <= top_; ++k) p_[k] = p_[k - 1] * a;
  }
  const Jet& base() const { return base_; }
  Jet operator()(int k) const {
    if (k <= top_) return p_[k];
    Jet r = p_[top_];
    for (int i = top_; i < k; ++i) r = r * base_;
    return r;
  }

 private:
  Scratch<Jet, kCap> p_;
  Jet base_;
  int top_ = 0;
};

// The power tables of ribbon i at one sample: lambda_i, lambda_i-1, D = lambda_i-1 + lambda_i,
// 1 / D and h_i, and whether x lies on a side where D vanishes (|D| / |grad D| below kOnSide).
struct RibbonPowers {
  Powers la, lb, dp, rp, hp;
  bool on_side = false;

  void build(const Jet& lam_i, const Jet& lam_prev, const Jet& D, const Jet& h, int d, int l) {
    const int m = 2 * l - 1;
    la.build(lam_i, d);
    lb.build(lam_prev, d);
    hp.build(h, l - 1);
    // Exponents of D: m - k - d for k = 0 .. l - 1 in basis(), l - d and l - 1 - k in evaluate().
    dp.build(D, std::max(m - d, l - 1));
    // hypot() is slow and needed only near the sides: 2 (|fu| + |fv|) >= 2 hypot(fu, fv), far
    // beyond any rounding, so where the cheap test says "off the side" the hypot() test does too.
    on_side = !(std::fabs(D.f) > 2 * kOnSide * (std::fabs(D.fu) + std::fabs(D.fv))) &&
              !(std::fabs(D.f) > kOnSide * std::hypot(D.fu, D.fv));
    // 1 / D is only needed (and only finite) off the sides where D vanishes.
    if (d - l > 0 && !on_side) rp.build(reciprocal(D), d - l);
  }
};

// la^ja lb^jb D^e with D = la + lb, total degree q = ja + jb + e >= 2. Where D vanishes (x on a
// side away from this ribbon, so la and lb vanish too, all to first order along the same normal
// n) the value and gradient are 0 and the Hessian is 2 c n n^T, c the product of the normal
// slopes: the exact limit of the 0/0 quotient. Same operations, in the same order, as
// pow(la, ja) * pow(lb, jb) * pow(D, e) (pow(1 / D, -e) for e < 0).
Jet homogeneous(const RibbonPowers& t, int ja, int jb, int e) {
  if (e >= 0) return t.la(ja) * t.lb(jb) * t.dp(e);
  if (!t.on_side) return t.la(ja) * t.lb(jb) * t.rp(-e);
  const Jet& D = t.dp.base();
  const double g = std::hypot(D.fu, D.fv);
  if (ja + jb + e >= 3 || g == 0) return Jet(0.0);
  const Jet &la = t.la.base(), &lb = t.lb.base();
  const double nx = D.fu / g, ny = D.fv / g;
  const double ca = la.fu * nx + la.fv * ny, cb = lb.fu * nx + lb.fv * ny;
  const double c = std::pow(ca, ja) * std::pow(cb, jb) * std::pow(g, e);
  return Jet(0, 0, 0, 2 * c * nx * nx, 2 * c * nx * ny, 2 * c * ny * ny);
}

double cross(Vec2 a, Vec2 b) {
  return a.x * b.y - a.y * b.x;
}

}  // namespace

GBRibbonPatch::GBRibbonPatch(ConcavePolygonDomain domain,
                             const std::vector<std::vector<std::vector<Vec3>>>& ribbons)
    : domain_(std::move(domain)) {
  const int n = domain_.side_count();
  if (static_cast<int>(ribbons.size()) != n)
    throw std::invalid_argument("gb-ribbons patch has " + std::to_string(ribbons.size()) +
                                " ribbons for a " + std::to_string(n) + "-sided domain");
  for (int i = 0; i < n; ++i) {
    const auto& r = ribbons[i];
    const std::string which = "ribbon " + std::to_string(i);
    if (r.size() < 2)
      throw std::invalid_argument(which + " needs at least 2 layers (G1 needs the second row)");
    if (r[0].size() < 2) throw std::invalid_argument(which + " needs degree >= 1");
    for (const auto& row : r)
      if (row.size() != r[0].size())
        throw std::invalid_argument(which + " has rows of different lengths");
    degree_.push_back(static_cast<int>(r[0].size()) - 1);
    layers_.push_back(static_cast<int>(r.size()));
    for (const auto& row : r)
      for (const Vec3& p : row)
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
          throw std::invalid_argument(which + " has a non-finite control point");
  }
  for (int i = 0; i < n; ++i) {
    const Vec3 a = ribbons[i][0].back(), b = ribbons[(i + 1) % n][0].front();
    const double scale = 1 + std::max({std::fabs(a.x), std::fabs(a.y), std::fabs(a.z)});
    if (glm::length(a - b) > 1e-12 * scale)
      throw std::invalid_argument("ribbon " + std::to_string(i) + " does not end where ribbon " +
                                  std::to_string((i + 1) % n) + " starts");
    const Vec2 ea = domain_.vertex(i) - domain_.vertex(i - 1);
    const Vec2 eb = domain_.vertex(i + 1) - domain_.vertex(i);
    if (!(std::fabs(cross(ea, eb)) > 1e-9 * glm::length(ea) * glm::length(eb)))
      throw std::invalid_argument("domain corner " + std::to_string(i) + " is straight");
  }
  std::size_t count = 0;
  for (int i = 0; i < n; ++i) {
    offset_.push_back(count);
    count += degree_[i] + (layers_[i] - 1) * (degree_[i] + 1);
  }
  offset_.push_back(count);
  fast_evaluate_ = n <= kMaxSides;
  points_.assign(count, Vec3(0));
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < layers_[i]; ++k)
      for (int j = 0; j <= degree_[i]; ++j)
        if (k > 0 || j < degree_[i]) points_[index(i, j, k)] = ribbons[i][k][j];
  check_parameterisation();
}

std::size_t GBRibbonPatch::index(int side, int j, int k) const {
  const int n = sides();
  side = ((side % n) + n) % n;
  const int d = degree_[side];
  if (k == 0) return j == d ? offset_[(side + 1) % n] : offset_[side] + j;
  return offset_[side] + d + (k - 1) * (d + 1) + j;
}

ControlPointKind GBRibbonPatch::kind(std::size_t k) const {
  const auto it = std::upper_bound(offset_.begin(), offset_.end(), k);
  const int side = static_cast<int>(it - offset_.begin()) - 1;
  return k - offset_[side] < std::size_t(degree_[side]) ? ControlPointKind::Boundary
                                                        : ControlPointKind::Inner;
}

std::vector<std::vector<std::vector<Vec3>>> GBRibbonPatch::ribbons() const {
  std::vector<std::vector<std::vector<Vec3>>> r(sides());
  for (int i = 0; i < sides(); ++i) {
    r[i].assign(layers_[i], std::vector<Vec3>(degree_[i] + 1));
    for (int k = 0; k < layers_[i]; ++k)
      for (int j = 0; j <= degree_[i]; ++j) r[i][k][j] = point(i, j, k);
  }
  return r;
}

std::vector<BezierCurve> GBRibbonPatch::boundary_curves() const {
  std::vector<BezierCurve> c;
  for (const auto& r : ribbons()) c.emplace_back(r[0]);
  return c;
}

void GBRibbonPatch::basis(Vec2 x, std::span<Jet> out) const {
  const int n = sides();
  const auto& v = domain_.vertices();
  std::fill(out.begin(), out.end(), Jet(0.0));
  for (int i = 0; i < n; ++i)
    if (x == v[i]) return corner_basis(i, out);
  std::vector<Jet> lam(n), h(n), D(n);
  mean_value_coordinates(v, x, lam);
  const auto at = [n](const std::vector<Jet>& a, int i) -> const Jet& { return a[(i + n) % n]; };
  for (int i = 0; i < n; ++i) {
    D[i] = at(lam, i - 1) + lam[i];
    // Summing the other coordinates (instead of 1 - D) keeps h_i exactly tiny on side i.
    h[i] = Jet(0.0);
    for (int j = 1; j < n - 1; ++j) h[i] += at(lam, i + j);
  }
  Jet sum(0.0);
  RibbonPowers t;
  for (int i = 0; i < n; ++i) {
    const int d = degree_[i], m = 2 * layers_[i] - 1;
    const Jet h2 = h[i] * h[i], hp2 = at(h, i - 1) * at(h, i - 1),
              hn2 = at(h, i + 1) * at(h, i + 1);
    const Jet alpha = hp2 / (hp2 + h2), beta = hn2 / (hn2 + h2);
    t.build(lam[i], at(lam, i - 1), D[i], h[i], d, layers_[i]);
    for (int k = 0; k < layers_[i]; ++k) {
      const Jet hk = binomial_of(m, k) * t.hp(k);
      for (int j = 0; j <= d; ++j) {
        const Jet mu = 2 * j < d ? alpha : 2 * j == d ? Jet(1.0) : beta;
        const Jet b = binomial_of(d, j) * homogeneous(t, j, d - j, m - k - d) * hk * mu;
        out[index(i, j, k)] += b;
        sum += b;
      }
    }
  }
  const Jet inv = reciprocal(sum);
  for (Jet& b : out) b = b * inv;
}

SurfaceJet GBRibbonPatch::evaluate(Vec2 x) const {
  const int n = sides();
  const auto& v = domain_.vertices();
  // At a vertex the weights are 0/0 and basis() has the exact corner limits; more sides than the
  // scratch arrays below hold (the codec accepts at most kMaxSides) take the reference path too.
  if (!fast_evaluate_) return Patch::evaluate(x);
  for (int i = 0; i < n; ++i)
    if (x == v[i]) return Patch::evaluate(x);
  // S = N / W with N = sum b_jk C_jk, W = sum b_jk, summed directly instead of normalising every
  // basis function (no per-sample heap allocation, no pow() per term). Off the limit case,
  //   b_jk = [binom(d, j) lambda_i^j lambda_i-1^(d-j) D_i^(l-d) mu_j] [binom(m, k) h_i^k
  //          D_i^(l-1-k)] = a_j H_k,
  // so N_i = sum_k H_k (sum_j a_j C_jk) and W_i = (sum_j a_j)(sum_k H_k): a few jet products
  // per row and per j instead of several per term. The lowest power of D (negative for d > l) goes
  // with the lambdas, as in basis(), so the huge 1 / D^(d-l) near other ribbons' sides meets the
  // tiny lambda powers first instead of overflowing with h's. Equal to the basis() sum up to
  // rounding.
  Scratch<Jet, kMaxSides> lam, h;
  mean_value_coordinates(v, x, std::span<Jet>(lam.data(), n));
  const auto at = [n](const Scratch<Jet, kMaxSides>& a, int i) -> const Jet& {
    return a[(i + n) % n];
  };
  for (int i = 0; i < n; ++i) {
    // As in basis(): summing the other coordinates keeps h_i exactly tiny on side i.
    h[i] = Jet(0.0);
    for (int j = 1; j < n - 1; ++j) h[i] += at(lam, i + j);
  }
  // Summed relative to the corner point of the largest lambda: near a corner the two ribbons
  // meeting there give that point weights whose second derivatives are huge (those of mu grow
  // like 1 / distance^2) and cancel only in their sum. Multiplied by the point before summing,
  // the cancellation would cost ~|C| 1e-16 / distance^2 (worse than basis(), which adds the two
  // weights first); relative to the point itself those terms are exactly zero.
  int near = 0;
  for (int i = 1; i < n; ++i)
    if (lam[i].f > lam[near].f) near = i;
  const Vec3 origin = points_[offset_[(near + 1) % n]];
  // h_i^2 once per side, and 1 / (h_i^2 + h_i+1^2) once per pair of neighbouring sides: it is
  // the denominator of both beta_i and alpha_i+1 (the same sum, as addition commutes).
  Scratch<Jet, kMaxSides> h2, r;
  for (int i = 0; i < n; ++i) h2[i] = h[i] * h[i];
  for (int i = 0; i < n; ++i) r[i] = reciprocal(at(h2, i + 1) + h2[i]);
  Jet w(0.0), sx(0.0), sy(0.0), sz(0.0);
  RibbonPowers t;
  Scratch<Jet, kMaxDegree + 1> A;
  for (int i = 0; i < n; ++i) {
    const int d = degree_[i], l = layers_[i], m = 2 * l - 1;
    const Jet alpha = at(h2, i - 1) * at(r, i - 1), beta = at(h2, i + 1) * r[i];
    t.build(lam[i], at(lam, i - 1), at(lam, i - 1) + lam[i], h[i], d, l);
    // Storage of C^i_{j,k}: see index(); row 0 ends at the next ribbon's first point.
    const std::size_t row0 = offset_[i], end0 = offset_[(i + 1) % n], inner = offset_[i] + d;
    const auto point_at = [&](int j, int k) -> Vec3 {
      if (k > 0) return points_[inner + (k - 1) * (d + 1) + j] - origin;
      return points_[j < d ? row0 + j : end0] - origin;
    };
    if ((t.on_side && d > l) || d > kMaxDegree) {
      // x on a side where D_i vanishes and some exponent of D_i is negative: the terms are the
      // one-sided limits of homogeneous(), which do not factor; this is rare (boundary
      // samples), so sum term by term as basis() does (so are degrees beyond A's size).
      for (int k = 0; k < l; ++k) {
        const Jet hk = binomial_of(m, k) * t.hp(k);
        for (int j = 0; j <= d; ++j) {
          const Jet mu = 2 * j < d ? alpha : 2 * j == d ? Jet(1.0) : beta;
          const Jet b = binomial_of(d, j) * homogeneous(t, j, d - j, m - k - d) * hk * mu;
          const Vec3 c = point_at(j, k);
          sx += b * c.x, sy += b * c.y, sz += b * c.z;
          w += b;
        }
      }
      continue;
    }
    Jet asum(0.0), hsum(0.0);
    for (int j = 0; j <= d; ++j) {
      // homogeneous(t, j, d - j, l - d) off the limit case.
      A[j] = binomial_of(d, j) * (t.la(j) * t.lb(d - j) * (l >= d ? t.dp(l - d) : t.rp(d - l)));
      if (2 * j < d) A[j] = A[j] * alpha;
      if (2 * j > d) A[j] = A[j] * beta;
      asum += A[j];
    }
    // Rows first: l jet products per coordinate instead of d + 1 (l <= d + 1 in practice).
    for (int k = 0; k < l; ++k) {
      const Jet Hk = binomial_of(m, k) * t.hp(k) * t.dp(l - 1 - k);
      hsum += Hk;
      Jet vx(0.0), vy(0.0), vz(0.0);
      for (int j = 0; j <= d; ++j) {
        const Vec3 c = point_at(j, k);
        vx += A[j] * c.x, vy += A[j] * c.y, vz += A[j] * c.z;
      }
      sx += Hk * vx, sy += Hk * vy, sz += Hk * vz;
    }
    w += asum * hsum;
  }
  const Jet inv = reciprocal(w);
  const Jet px = sx * inv, py = sy * inv, pz = sz * inv;
  SurfaceJet s;
  s.p = origin + Vec3(px.f, py.f, pz.f);
  s.su = {px.fu, py.fu, pz.fu};
  s.sv = {px.fv, py.fv, pz.fv};
  s.suu = {px.fuu, py.fuu, pz.fuu};
  s.suv = {px.fuv, py.fuv, pz.fuv};
  s.svv = {px.fvv, py.fvv, pz.fvv};
  return s;
}

void GBRibbonPatch::corner_basis(int vtx, std::span<Jet> out) const {
  // Corner between side a = vtx (ending here) and side b = vtx + 1 (starting here). Known
  // exactly: the point, the first derivative along both sides (the curves' end tangents) and
  // the second derivative along both sides. The mixed term D^2 S[e_a, e_b] is the mean of the
  // two ribbons' twists (ribbon a: d/ds d/dh at (1, 0); ribbon b, whose h runs against e_a:
  // minus its twist at (0, 0)).
  const int n = sides(), a = vtx, b = (vtx + 1) % n;
  struct Coef {
    double val = 0, da = 0, db = 0, aa = 0, bb = 0, ab = 0;
  };
  std::vector<Coef> c(size());
  const int d = degree_[a], m = 2 * layers_[a] - 1;
  const int e = degree_[b], mb = 2 * layers_[b] - 1;
  c[index(a, d, 0)].val += 1;
  c[index(a, d, 0)].da += d;
  c[index(a, d - 1, 0)].da -= d;
  c[index(b, 1, 0)].db += e;
  c[index(b, 0, 0)].db -= e;
  if (d >= 2) {
    c[index(a, d, 0)].aa += d * (d - 1);
    c[index(a, d - 1, 0)].aa -= 2 * d * (d - 1);
    c[index(a, d - 2, 0)].aa += d * (d - 1);
  }
  if (e >= 2) {
    c[index(b, 0, 0)].bb += e * (e - 1);
    c[index(b, 1, 0)].bb -= 2 * e * (e - 1);
    c[index(b, 2, 0)].bb += e * (e - 1);
  }
  const double ta = 0.5 * m * d, tb = -0.5 * mb * e;
  c[index(a, d, 1)].ab += ta;
  c[index(a, d - 1, 1)].ab -= ta;
  c[index(a, d, 0)].ab -= ta;
  c[index(a, d - 1, 0)].ab += ta;
  c[index(b, 1, 1)].ab += tb;
  c[index(b, 0, 1)].ab -= tb;
  c[index(b, 1, 0)].ab -= tb;
  c[index(b, 0, 0)].ab += tb;
  const Vec2 ea = domain_.vertex(a) - domain_.vertex(a - 1);
  const Vec2 eb = domain_.vertex(a + 1) - domain_.vertex(a);
  const double det = cross(ea, eb);
  // Columns of E^-1, E = [e_a e_b]: grad = E^-T (da, db), Hessian = E^-T K E^-1.
  const double p = eb.y / det, q = -eb.x / det, r = -ea.y / det, s = ea.x / det;
  for (std::size_t k = 0; k < c.size(); ++k) {
    const Coef& f = c[k];
    out[k] = Jet(f.val, p * f.da + r * f.db, q * f.da + s * f.db,
                 p * p * f.aa + 2 * p * r * f.ab + r * r * f.bb,
                 p * q * f.aa + (p * s + r * q) * f.ab + r * s * f.bb,
                 q * q * f.aa + 2 * q * s * f.ab + s * s * f.bb);
  }
}

void GBRibbonPatch::check_parameterisation() const {
  // Mean value coordinates can be negative behind reflex vertices; where lambda_i-1 + lambda_i
  // reaches 0 inside the domain, s_i has a pole. Reject such domains instead of producing
  // non-finite samples (checked on a tessellation's interior points).
  // Inside a convex polygon they are all positive (Floater 2003), so only a domain with a reflex
  // corner needs the sampled check; it cost ~3 ms per face, paid on every re-fill of a drag.
  const auto& v = domain_.vertices();
  const int count = static_cast<int>(v.size());
  bool convex = true;
  for (int i = 0; i < count && convex; ++i)
    convex = cross(domain_.vertex(i) - domain_.vertex(i - 1),
                   domain_.vertex(i + 1) - domain_.vertex(i)) > 0;
  if (convex) return;
  const Tessellation t = domain_.tessellate(24);
  std::vector<bool> boundary(t.points.size(), false);
  for (const auto& side : t.sides)
    for (uint32_t k : side) boundary[k] = true;
  const int n = sides();
  std::vector<Jet> lam(n), phi(size());
  for (std::size_t k = 0; k < t.points.size(); ++k) {
    if (boundary[k]) continue;
    mean_value_coordinates(domain_.vertices(), t.points[k], lam);
    for (int i = 0; i < n; ++i)
      if (!(lam[(i + n - 1) % n].f + lam[i].f > 0))
        throw std::invalid_argument(
            "domain too concave for mean value coordinates: lambda_i-1 + lambda_i <= 0 for side " +
            std::to_string(i));
    basis(t.points[k], phi);
    for (const Jet& j : phi)
      if (!std::isfinite(j.f) || !std::isfinite(j.fuu) || !std::isfinite(j.fvv))
        throw std::invalid_argument("gb-ribbons blend is singular inside the domain");
  }
}

}  // namespace pl
