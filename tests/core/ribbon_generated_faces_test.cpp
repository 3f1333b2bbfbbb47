// Faces beyond the reference folder: explicit-ribbon faces of 3 to 8 sides made by the generator
// that made the reference faces (tests/data/schemes/README.md, with other phases), filled by
// every ribbon scheme and checked against a second evaluation written here from the schemes'
// definitions alone, in plain doubles (no jets, no shared code with core/patch/transfinite): the
// domain (regular n-gon, or the side-based scheme's angular polygon), the parameterizations, the
// blends with their 1e-8 branches, the corner patches, the central point of the midpoint schemes
// and the elastic scheme's 3 x 3 system solved by Gaussian elimination. With the research
// library's forward-difference twists on both sides, and with exact twists on both sides, the
// patches agree to 1e-12 of the face's size at random domain points and at side points; a face
// read from a scene file and tessellated as the exporters tessellate it has every mesh vertex on
// that second evaluation to the same precision.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <sstream>

#include "core/domain/tessellation_cache.hpp"
#include "core/eval/scene_surfaces.hpp"
#include "core/io/scene_io.hpp"
#include "core/mesh/surface_mesh.hpp"
#include "ribbon_test_util.hpp"

namespace pl {
namespace {

using transfinite::RibbonScheme;
using transfinite::TwistEstimate;
constexpr double kPi = std::numbers::pi;

// ---------------------------------------------------------------------------------------------
// The generator: corners on a wobbly circle, cubic sides bulging outwards and up, cross
// derivatives fixed at the ends by the neighbours' tangents and lifted inside.
struct Face {
  std::vector<std::array<Vec3, 4>> p;  // boundary cubics
  std::vector<std::vector<Vec3>> d;    // cross derivatives (degree 2 or 3)
};

Face generated_face(int n, double phi, int cross_degree) {
  std::vector<Vec3> c(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k) {
    const double theta = 2 * kPi * k / n + 0.07 * std::sin(2.3 * k + phi) + (n == 4 ? kPi / 4 : 0);
    const double r = 10 * (1 + 0.06 * std::sin(1.7 * k + 2 * phi));
    c[std::size_t(k)] = Vec3(r * std::cos(theta) + 0.4, r * std::sin(theta) - 0.3,
                             0.8 * std::sin(2 * theta + phi) + 0.3 * std::cos(3 * theta - phi));
  }
  Face f;
  std::vector<Vec2> inward(static_cast<std::size_t>(n));
  std::vector<double> chord(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k) {
    const Vec3 a = c[std::size_t((k + n - 1) % n)], b = c[std::size_t(k)];
    const Vec2 t(b.x - a.x, b.y - a.y);
    const double len = std::hypot(t.x, t.y);
    const Vec2 nu(-t.y / len, t.x / len);  // left of the counter-clockwise loop: inwards
    inward[std::size_t(k)] = nu, chord[std::size_t(k)] = len;
    const double out1 = (0.05 + 0.02 * std::sin(3.1 * k + phi)) * len;
    const double out2 = (0.05 + 0.02 * std::cos(2.7 * k + phi)) * len;
    Vec3 q1 = a + (b - a) / 3.0, q2 = a + 2.0 * (b - a) / 3.0;
    q1 -= Vec3(nu.x * out1, nu.y * out1, -0.6 * std::sin(1.3 * k + 2 * phi));
    q2 -= Vec3(nu.x * out2, nu.y * out2, -0.5 * std::cos(1.9 * k + phi));
    f.p.push_back({a, q1, q2, b});
  }
  for (int k = 0; k < n; ++k) {
    const auto& prev = f.p[std::size_t((k + n - 1) % n)];
    const auto& next = f.p[std::size_t((k + 1) % n)];
    const Vec3 d0 = 3.0 * (prev[2] - prev[3]), d1 = 3.0 * (next[1] - next[0]);
    const Vec2 nu = inward[std::size_t(k)];
    const double len = chord[std::size_t(k)];
    const double a = (0.12 + 0.04 * std::sin(1.1 * k + phi)) * len;
    const double a2 = (0.12 + 0.04 * std::cos(0.9 * k + phi)) * len;
    const double up = (0.40 + 0.08 * std::sin(1.7 * k + 2 * phi)) * len;
    const double up2 = (0.40 + 0.08 * std::cos(1.3 * k + phi)) * len;
    if (cross_degree == 2) {
      f.d.push_back({d0, 0.5 * (d0 + d1) + Vec3(a * nu.x, a * nu.y, up), d1});
    } else {
      f.d.push_back({d0, (2.0 * d0 + d1) / 3.0 + Vec3(a * nu.x, a * nu.y, up),
                     (d0 + 2.0 * d1) / 3.0 + Vec3(a2 * nu.x, a2 * nu.y, up2), d1});
    }
  }
  return f;
}

// ---------------------------------------------------------------------------------------------
// The second evaluation.
constexpr double kEps = 1e-8;

// A Bézier curve by the Cox-de Boor triangle on the knots 0..0 1..1 (the research library's
// rounding, which its forward-difference twists magnify 1e4 times).
Vec3 bezier_by_basis(const std::vector<Vec3>& cp, double u) {
  const std::size_t m = cp.size() - 1;
  std::vector<double> b{1.0};
  for (std::size_t j = 1; j <= m; ++j) {
    double saved = 0;
    for (std::size_t r = 0; r < j; ++r) {
      const double tmp = b[r] / ((1 - u) + u);
      b[r] = saved + tmp * (1 - u);
      saved = tmp * u;
    }
    b.push_back(saved);
  }
  Vec3 p(0);
  for (std::size_t r = 0; r <= m; ++r) p += cp[r] * b[r];
  return p;
}
// Its derivative through the hodograph.
Vec3 bezier_derivative(const std::vector<Vec3>& cp, double u) {
  std::vector<Vec3> h;
  for (std::size_t r = 0; r + 1 < cp.size(); ++r)
    h.push_back(double(cp.size() - 1) * (cp[r + 1] - cp[r]));
  return bezier_by_basis(h, u);
}

struct Reference {
  int n = 0;
  std::vector<std::vector<Vec3>> P, D;
  std::vector<Vec2> v;
  Vec2 centre{0};
  std::vector<Vec3> C, T1, T2, tw1, tw2;  // corner data
  Vec3 central{0};
  int at(int i) const { return ((i % n) + n) % n; }

  Vec3 ribbon(int i, double s, double d) const {
    return bezier_by_basis(P[std::size_t(at(i))], s) +
           d * bezier_by_basis(D[std::size_t(at(i))], s);
  }
  static double gamma(double d) { return d / (2 * d + 1); }
  Vec3 side_interpolant(int i, double s, double d) const {
    return ribbon(i, std::clamp(s, 0.0, 1.0), std::max(gamma(d), 0.0));
  }
  Vec3 corner_patch(int i, double a, double b) const {
    const int k = at(i);
    const double a1 = std::clamp(gamma(a), 0.0, 1.0), b1 = std::clamp(gamma(b), 0.0, 1.0);
    const Vec3 w = std::abs(a1 + b1) < kEps
                       ? Vec3(0)
                       : (a1 * tw2[std::size_t(k)] + b1 * tw1[std::size_t(k)]) / (a1 + b1);
    return C[std::size_t(k)] + a1 * T1[std::size_t(k)] + b1 * T2[std::size_t(k)] + w * a1 * b1;
  }
  Vec3 corner_interpolant(int i, const std::vector<double>& s) const {
    const double si = s[std::size_t(at(i))], sn = s[std::size_t(at(i + 1))];
    return side_interpolant(i, si, sn) + side_interpolant(i + 1, sn, 1 - si) -
           corner_patch(i, 1 - si, sn);
  }

  // Side i's local frame: (w . du, w . dv) / |du|^2, dv the inward normal.
  Vec2 local(int i, Vec2 w) const {
    const Vec2 du = v[std::size_t(at(i))] - v[std::size_t(at(i - 1))];
    Vec2 dv(du.y, -du.x);
    if (glm::dot(centre - v[std::size_t(at(i))], dv) < 0) dv = -dv;
    const double l2 = glm::dot(du, du);
    return Vec2(glm::dot(w, du) / l2, glm::dot(w, dv) / l2);
  }
  std::pair<double, double> bilinear(int i, Vec2 x) const {
    const Vec2 p1 = local(i, v[std::size_t(at(i - 2))] - v[std::size_t(at(i - 1))]);
    const Vec2 p2 = local(i, v[std::size_t(at(i + 1))] - v[std::size_t(at(i))]);
    const Vec2 p = local(i, x - v[std::size_t(at(i - 1))]);
    const double a = p1.y - p2.y;
    const double b = p.x * p2.y - (p.x + 1) * p1.y + (p1.x - p2.x) * p.y;
    const double c = p.x * p1.y - p.y * p1.x;
    double s;
    if (std::abs(a) < kEps) {
      s = std::abs(b) < kEps ? 0 : -c / b;
    } else {
      double disc = b * b - 4 * a * c;
      if (disc < kEps) disc = 0;
      const double r1 = -b / (2 * a) + std::sqrt(disc) / (2 * a);
      const double r2 = -b / (2 * a) - std::sqrt(disc) / (2 * a);
      const double hi = std::max(r1, r2), lo = std::min(r1, r2);
      s = std::max(0.0, hi - 1) < std::max(0.0, -lo) ? hi : lo;
    }
    const double d = p.y / (p1.y * (1 - s) + p2.y * s);
    return {s, d};
  }
  std::vector<double> wachspress(Vec2 x) const {
    const auto cross = [](Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; };
    std::vector<double> A(static_cast<std::size_t>(n)), w(static_cast<std::size_t>(n));
    for (int j = 0; j < n; ++j)
      A[std::size_t(j)] = 0.5 * cross(x - v[std::size_t(j)], x - v[std::size_t(at(j + 1))]);
    double sum = 0;
    for (int i = 0; i < n; ++i) {
      const double B = 0.5 * cross(x - v[std::size_t(at(i - 1))], x - v[std::size_t(at(i + 1))]);
      double not_prev = 1, not_this = 1, neither = 1;
      for (int j = 0; j < n; ++j) {
        if (j != at(i - 1)) not_prev *= A[std::size_t(j)];
        if (j != i) not_this *= A[std::size_t(j)];
        if (j != at(i - 1) && j != i) neither *= A[std::size_t(j)];
      }
      w[std::size_t(i)] = not_prev + not_this - B * neither;
      sum += w[std::size_t(i)];
    }
    for (double& x_ : w) x_ /= sum;
    return w;
  }
  // Barycentric (s, d); the fallback where lambda_{i-1} + lambda_i vanishes gets no weight.
  void barycentric(Vec2 x, std::vector<double>& s, std::vector<double>& d) const {
    const std::vector<double> l = wachspress(x);
    for (int i = 0; i < n; ++i) {
      const double lp = l[std::size_t(at(i - 1))], li = l[std::size_t(i)];
      s[std::size_t(i)] = lp + li < kEps ? 0.5 : li / (lp + li);
      d[std::size_t(i)] = 1 - lp - li;
    }
  }
  static double hermite(double t) { return std::pow(1 - t, 3) + 3 * std::pow(1 - t, 2) * t; }

  // The side-singular blend of any list of values: the small ones share 1, else value^-2.
  static std::vector<double> singular_blend(const std::vector<double>& d) {
    std::vector<double> w(d.size(), 0.0);
    int small = 0;
    for (double x : d) small += x < kEps;
    if (small > 0) {
      for (std::size_t i = 0; i < d.size(); ++i) w[i] = d[i] < kEps ? 1.0 / small : 0;
      return w;
    }
    double sum = 0;
    for (double x : d) sum += 1 / (x * x);
    for (std::size_t i = 0; i < d.size(); ++i) w[i] = 1 / (d[i] * d[i]) / sum;
    return w;
  }
  std::vector<double> corner_blend(const std::vector<double>& d) const {
    std::vector<double> w(std::size_t(n), 0.0);
    int small = 0;
    for (double x : d) small += x < kEps;
    const auto D = [&](int i) { return d[std::size_t(at(i))]; };
    for (int i = 0; i < n; ++i) {
      if (small == 0) {
        double sum = 0;
        for (int j = 0; j < n; ++j) sum += 1 / std::pow(D(j) * D(j + 1), 2);
        w[std::size_t(i)] = 1 / std::pow(D(i) * D(i + 1), 2) / sum;
      } else if (small == 1) {
        if (D(i) < kEps)
          w[std::size_t(i)] =
              1 / (D(i + 1) * D(i + 1)) / (1 / (D(i + 1) * D(i + 1)) + 1 / (D(i - 1) * D(i - 1)));
        else if (D(i + 1) < kEps)
          w[std::size_t(i)] = 1 / (D(i) * D(i)) / (1 / (D(i) * D(i)) + 1 / (D(i + 2) * D(i + 2)));
      } else {
        w[std::size_t(i)] = D(i) < kEps && D(i + 1) < kEps ? 1 : 0;
      }
    }
    return w;
  }
  std::vector<double> deficient_blend(const std::vector<double>& s,
                                      const std::vector<double>& d) const {
    std::vector<double> w(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
      const double di = d[std::size_t(i)], dn = d[std::size_t(at(i + 1))];
      const double si = s[std::size_t(i)], sn = s[std::size_t(at(i + 1))];
      w[std::size_t(i)] =
          di < kEps && dn < kEps
              ? 1
              : (dn * hermite(1 - si) * hermite(di) + di * hermite(sn) * hermite(dn)) / (di + dn);
    }
    return w;
  }

  // The scheme at x, the midpoint schemes with central point `c`.
  Vec3 eval(RibbonScheme scheme, Vec2 x, Vec3 c) const {
    std::vector<double> s(static_cast<std::size_t>(n)), d(static_cast<std::size_t>(n));
    Vec3 out(0);
    switch (scheme) {
      case RibbonScheme::SideBased: {
        for (int i = 0; i < n; ++i) {
          s[std::size_t(i)] = bilinear(i, x).first;
          double m = 0;
          for (int j = 0; j < n; ++j)
            m = std::max(m, local(i, v[std::size_t(j)] - v[std::size_t(i)]).y);
          d[std::size_t(i)] = local(i, x - v[std::size_t(i)]).y / m;
        }
        const auto w = singular_blend(d);
        for (int i = 0; i < n; ++i)
          out += w[std::size_t(i)] * side_interpolant(i, s[std::size_t(i)], d[std::size_t(i)]);
        return out;
      }
      case RibbonScheme::CornerBased: {
        for (int i = 0; i < n; ++i) std::tie(s[std::size_t(i)], d[std::size_t(i)]) = bilinear(i, x);
        const auto w = corner_blend(d);
        for (int i = 0; i < n; ++i) out += w[std::size_t(i)] * corner_interpolant(i, s);
        return out;
      }
      case RibbonScheme::GeneralizedCoons: {
        for (int i = 0; i < n; ++i) s[std::size_t(i)] = bilinear(i, x).first;
        for (int i = 0; i < n; ++i)
          d[std::size_t(i)] = (1 - s[std::size_t(at(i - 1))]) * hermite(s[std::size_t(i)]) +
                              s[std::size_t(at(i + 1))] * (1 - hermite(s[std::size_t(i)]));
        const auto w = corner_blend(d);
        for (int i = 0; i < n; ++i)
          out +=
              (w[std::size_t(i)] + w[std::size_t(at(i - 1))]) *
                  side_interpolant(i, s[std::size_t(i)], d[std::size_t(i)]) -
              w[std::size_t(i)] * corner_patch(i, 1 - s[std::size_t(i)], s[std::size_t(at(i + 1))]);
        return out;
      }
      case RibbonScheme::CompositeRibbon: {
        barycentric(x, s, d);
        const auto w = corner_blend(d);
        for (int i = 0; i < n; ++i) {
          const double si = s[std::size_t(i)], di = d[std::size_t(i)];
          const Vec3 cr = side_interpolant(i, si, di) * hermite(di) +
                          side_interpolant(i - 1, 1 - di, si) * hermite(si) +
                          side_interpolant(i + 1, di, 1 - si) * (1 - hermite(si)) -
                          corner_patch(i - 1, di, si) * hermite(si) * hermite(di) -
                          corner_patch(i, 1 - si, di) * (1 - hermite(si)) * hermite(di);
          out += 0.5 * (w[std::size_t(i)] + w[std::size_t(at(i - 1))]) * cr;
        }
        return out;
      }
      case RibbonScheme::Midpoint: {
        barycentric(x, s, d);
        const auto w = deficient_blend(s, d);
        double sum = 0;
        for (int i = 0; i < n; ++i)
          out += w[std::size_t(i)] * corner_interpolant(i, s), sum += w[std::size_t(i)];
        return out + (1 - sum) * c;
      }
      case RibbonScheme::MidpointCoons: {
        barycentric(x, s, d);
        std::vector<double> dc(static_cast<std::size_t>(n));
        for (int i = 0; i < n; ++i) {
          const std::vector<double> b = singular_blend(
              {d[std::size_t(i)], 1 - s[std::size_t(i)], 1 - d[std::size_t(i)], s[std::size_t(i)]});
          dc[std::size_t(i)] = d[std::size_t(i)] * (b[0] + b[2]) +
                               s[std::size_t(at(i + 1))] * b[1] +
                               (1 - s[std::size_t(at(i - 1))]) * b[3];
        }
        const auto w = deficient_blend(s, dc);
        double sum = 0;
        for (int i = 0; i < n; ++i) {
          out +=
              (w[std::size_t(i)] + w[std::size_t(at(i - 1))]) *
                  side_interpolant(i, s[std::size_t(i)], dc[std::size_t(i)]) -
              w[std::size_t(i)] * corner_patch(i, 1 - s[std::size_t(i)], s[std::size_t(at(i + 1))]);
          sum += w[std::size_t(i)];
        }
        return out + (1 - sum) * c;
      }
      case RibbonScheme::Elastic:
        return elastic(x);
    }
    return out;
  }

  Vec3 elastic(Vec2 x) const {
    double A[3][3] = {};
    Vec3 B[3] = {Vec3(0), Vec3(0), Vec3(0)};
    for (int i = 0; i < n; ++i) {
      const double s = std::clamp(bilinear(i, x).first, 0.0, 1.0);
      const Vec2 b = (1 - s) * v[std::size_t(at(i - 1))] + s * v[std::size_t(i)];
      const double du = x.x - b.x, dv = x.y - b.y, delta = std::hypot(du, dv);
      const Vec3 p = bezier_by_basis(P[std::size_t(i)], s);
      if (delta < 1e-5) return p;
      const Vec3 t = bezier_by_basis(D[std::size_t(i)], s) * delta;
      const double w = 1 / (delta * delta * delta);
      const double row0[3] = {2 * w, du * w, dv * w};
      const double row1[3] = {3 * du * w, 2 * du * du * w, 2 * du * dv * w};
      const double row2[3] = {3 * dv * w, 2 * du * dv * w, 2 * dv * dv * w};
      for (int c = 0; c < 3; ++c) A[0][c] += row0[c], A[1][c] += row1[c], A[2][c] += row2[c];
      B[0] += (2.0 * p + t) * w;
      B[1] += (3.0 * du * p + du * t) * w;
      B[2] += (3.0 * dv * p + dv * t) * w;
    }
    // Gaussian elimination with partial pivoting; X_0 is the surface.
    int row[3] = {0, 1, 2};
    for (int k = 0; k < 3; ++k) {
      int best = k;
      for (int j = k + 1; j < 3; ++j)
        if (std::abs(A[row[j]][k]) > std::abs(A[row[best]][k])) best = j;
      std::swap(row[k], row[best]);
      for (int j = k + 1; j < 3; ++j) {
        const double f = A[row[j]][k] / A[row[k]][k];
        for (int c = k; c < 3; ++c) A[row[j]][c] -= f * A[row[k]][c];
        B[row[j]] -= f * B[row[k]];
      }
    }
    Vec3 X[3];
    for (int k = 2; k >= 0; --k) {
      Vec3 r = B[row[k]];
      for (int c = k + 1; c < 3; ++c) r -= A[row[k]][c] * X[c];
      X[k] = r / A[row[k]][k];
    }
    return X[0];
  }
};

std::vector<Vec2> regular_polygon(int n) {
  if (n == 4) return {{1, 1}, {-1, 1}, {-1, -1}, {1, -1}};
  std::vector<Vec2> v;
  const double a = 2 * kPi / n;
  for (int i = 0; i < n; ++i) v.emplace_back(std::cos(a * i), std::sin(a * i));
  return v;
}

// The side-based scheme's domain from the curves: arc lengths by four-point Gauss-Legendre
// (nine-digit constants), corner angles scaled to sum to (n - 2) pi, the chain closed in
// proportion to arc length, scaled into [-1, 1]^2; and its centre.
std::pair<std::vector<Vec2>, Vec2> angular_polygon(const Reference& r) {
  const int n = r.n;
  const double g[2] = {0.861136312, 0.339981044}, gw[2] = {0.347854845, 0.652145155};
  std::vector<double> L(static_cast<std::size_t>(n)), phi(static_cast<std::size_t>(n));
  double total = 0, phi_sum = 0;
  for (int i = 0; i < n; ++i) {
    double len = 0;
    for (int k = 0; k < 2; ++k)
      for (double sign : {-1.0, 1.0})
        len += glm::length(bezier_derivative(r.P[std::size_t(i)], (sign * g[k] + 1) / 2)) * gw[k] *
               0.5;
    L[std::size_t(i)] = len, total += len;
    const Vec3 a = glm::normalize(bezier_derivative(r.P[std::size_t(i)], 1));
    const Vec3 b = glm::normalize(bezier_derivative(r.P[std::size_t(r.at(i + 1))], 0));
    phi[std::size_t(i)] = std::acos(std::clamp(-glm::dot(a, b), -1.0, 1.0));
    phi_sum += phi[std::size_t(i)];
  }
  std::vector<Vec2> w(static_cast<std::size_t>(n));
  double theta = 0;
  w[0] = Vec2(L[0], 0);
  for (int i = 1; i < n; ++i) {
    theta += kPi - phi[std::size_t(i - 1)] * (n - 2) * kPi / phi_sum;
    w[std::size_t(i)] =
        w[std::size_t(i - 1)] + L[std::size_t(i)] * Vec2(std::cos(theta), std::sin(theta));
  }
  std::vector<Vec2> v(static_cast<std::size_t>(n));
  double run = 0;
  for (int i = 0; i < n; ++i)
    run += L[std::size_t(i)],
        v[std::size_t(i)] = w[std::size_t(i)] - w[std::size_t(n - 1)] * (run / total);
  double x0 = 0, x1 = 0, y0 = 0, y1 = 0;
  for (const Vec2& p : v)
    x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
  const double width = std::max(x1 - x0, y1 - y0);
  for (Vec2& p : v) p = Vec2(-1, -1) + (p - Vec2(x0, y0)) * 2.0 / width;
  Vec2 c(0);
  double perimeter = 0;
  for (int i = 0; i < n; ++i) {
    const double li = glm::length(v[std::size_t(i)] - v[std::size_t(r.at(i - 1))]);
    const double ln = glm::length(v[std::size_t(r.at(i + 1))] - v[std::size_t(i)]);
    c += v[std::size_t(i)] * (li + ln), perimeter += li;
  }
  return {v, c / (2 * perimeter)};
}

Reference reference_of(const Face& f, RibbonScheme scheme, TwistEstimate twists) {
  Reference r;
  r.n = int(f.p.size());
  for (int i = 0; i < r.n; ++i) {
    r.P.emplace_back(f.p[std::size_t(i)].begin(), f.p[std::size_t(i)].end());
    r.D.push_back(f.d[std::size_t(i)]);
  }
  if (scheme == RibbonScheme::SideBased) {
    std::tie(r.v, r.centre) = angular_polygon(r);
  } else {
    r.v = regular_polygon(r.n);
  }
  const double h = 1e-4;
  for (int i = 0; i < r.n; ++i) {
    const auto& P = r.P[std::size_t(i)];
    const auto& Di = r.D[std::size_t(i)];
    const auto& Dn = r.D[std::size_t(r.at(i + 1))];
    r.C.push_back(bezier_by_basis(P, 1));
    r.T1.push_back(-bezier_derivative(P, 1));
    r.T2.push_back(bezier_derivative(r.P[std::size_t(r.at(i + 1))], 0));
    if (twists == TwistEstimate::ForwardDifference) {
      r.tw1.push_back((bezier_by_basis(Di, 1 - h) - bezier_by_basis(Di, 1)) / h);
      r.tw2.push_back((bezier_by_basis(Dn, h) - bezier_by_basis(Dn, 0)) / h);
    } else {
      r.tw1.push_back(-bezier_derivative(Di, 1));
      r.tw2.push_back(bezier_derivative(Dn, 0));
    }
  }
  if (scheme == RibbonScheme::Midpoint || scheme == RibbonScheme::MidpointCoons) {
    Vec3 m(0);
    for (int i = 0; i < r.n; ++i) m += r.ribbon(i, 0.5, 0.25);
    m /= double(r.n);
    const Vec3 s0 = r.eval(scheme, r.centre, Vec3(0));
    const double deficiency = (r.eval(scheme, r.centre, Vec3(1, 0, 0)) - s0).x;
    r.central = std::abs(deficiency) < kEps ? m : (m - s0) / deficiency;
  }
  return r;
}

std::vector<RibbonSide> sides_of(const Face& f) {
  std::vector<RibbonSide> sides;
  for (std::size_t i = 0; i < f.p.size(); ++i)
    sides.push_back(
        {test::bezier_curve_of({f.p[i].begin(), f.p[i].end()}), test::bezier_curve_of(f.d[i])});
  return sides;
}

double face_size(const Face& f) {
  Vec3 lo(1e300), hi(-1e300);
  for (const auto& p : f.p)
    for (const Vec3& q : p) lo = glm::min(lo, q), hi = glm::max(hi, q);
  return glm::length(hi - lo);
}

// Eleven points on every side, two near every corner, and random points inside the domain
// (rejection in the bounding box, 1e-4 off every side line: within 1e-5 of a side the library's
// elastic scheme returns the boundary point itself, a step of about 1e-5 |D| that PatchLab does
// not copy).
std::vector<Vec2> domain_points(const std::vector<Vec2>& v, unsigned seed) {
  const int n = int(v.size());
  std::vector<Vec2> out;
  for (int i = 0; i < n; ++i)
    for (int k = 0; k <= 10; ++k)
      out.push_back((1 - k / 10.0) * v[std::size_t((i + n - 1) % n)] +
                    (k / 10.0) * v[std::size_t(i)]);
  // Towards every corner, where two sides' weights compete (1e-2 and 1e-3 of the domain from the
  // vertex, towards the vertices' average).
  Vec2 mean(0);
  for (const Vec2& p : v) mean += p / double(n);
  for (const Vec2& p : v)
    for (double r : {1e-2, 1e-3}) out.push_back(p + r * glm::normalize(mean - p));
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  while (out.size() < std::size_t(13 * n + 200)) {
    const Vec2 x(u(rng), u(rng));
    bool inside = true;
    for (int i = 0; i < n && inside; ++i) {
      const Vec2 a = v[std::size_t((i + n - 1) % n)], b = v[std::size_t(i)];
      inside = ((b - a).x * (x - a).y - (b - a).y * (x - a).x) / glm::length(b - a) > 1e-4;
    }
    if (inside) out.push_back(x);
  }
  return out;
}

struct Case {
  int n;
  double phi;
  int cross_degree;
};
constexpr Case kCases[] = {{3, 0.45, 2}, {4, 2.2, 3},  {5, 1.6, 3},
                           {6, 0.15, 2}, {7, 1.05, 3}, {8, 2.75, 2}};

TEST(RibbonGeneratedFaces, EverySchemeAgreesWithASecondEvaluationOfItsDefinition) {
  for (const Case& c : kCases) {
    const Face f = generated_face(c.n, c.phi, c.cross_degree);
    const double size = face_size(f);
    for (RibbonScheme scheme : transfinite::all_ribbon_schemes())
      for (TwistEstimate twists : {TwistEstimate::ForwardDifference, TwistEstimate::Exact}) {
        const Reference ref = reference_of(f, scheme, twists);
        RibbonPatchOptions o;
        o.twists = twists;
        const RibbonPatch patch(scheme, sides_of(f), o);  // the scheme's default domain
        double worst_domain = 0;
        for (int i = 0; i < c.n; ++i)
          worst_domain = std::max(worst_domain,
                                  glm::length(patch.polygon().vertex(i) - ref.v[std::size_t(i)]));
        EXPECT_LT(worst_domain, 1e-13) << ribbon_scheme_name(scheme) << " n=" << c.n;
        double worst = 0;
        for (Vec2 x : domain_points(ref.v, unsigned(c.n * 31 + 7))) {
          bool vertex = false;  // the patch takes the exact corner there, the formulas a limit
          for (const Vec2& v : ref.v) vertex = vertex || glm::length(x - v) < 1e-12;
          const Vec3 a = patch.evaluate(x).p,
                     b = vertex ? patch.evaluate(x).p : ref.eval(scheme, x, ref.central);
          worst = std::max(worst, glm::length(a - b) / size);
        }
        EXPECT_LT(worst, 1e-12) << ribbon_scheme_name(scheme) << " n=" << c.n << " phi=" << c.phi;
        if (twists == TwistEstimate::Exact)
          std::printf("[ generated ] n=%d phi=%.2f %-18s max difference %.3g relative\n", c.n,
                      c.phi, std::string(ribbon_scheme_name(scheme)).c_str(), worst);
      }
  }
}

std::string point_json(const Vec3& p) {
  std::ostringstream os;
  os.precision(17);
  os << "[" << p.x << ", " << p.y << ", " << p.z << "]";
  return os.str();
}

std::string curve_json(const std::vector<Vec3>& points) {
  std::string s = "{\"type\": \"bezier\", \"points\": [";
  for (std::size_t k = 0; k < points.size(); ++k) s += (k ? ", " : "") + point_json(points[k]);
  return s + "]}";
}

TEST(RibbonGeneratedFaces, AFaceReadFromAFileIsTessellatedOnItsDefinition) {
  // Written as a user writes it (no domain, no twist setting), read, tessellated at the exporters'
  // default density: every mesh vertex is the second evaluation at the vertex's domain point.
  const Case c = kCases[4];  // seven sides
  const Face f = generated_face(c.n, c.phi, c.cross_degree);
  std::string text = "{\"patchlab\": 1, \"patches\": [";
  const auto schemes = transfinite::all_ribbon_schemes();
  for (std::size_t k = 0; k < schemes.size(); ++k) {
    text += std::string(k ? ", " : "") + "{\"type\": \"ribbons\", \"scheme\": \"" +
            std::string(ribbon_scheme_name(schemes[k])) + "\", \"sides\": [";
    for (int i = 0; i < c.n; ++i)
      text += std::string(i ? ", " : "") + "{\"curve\": " +
              curve_json({f.p[std::size_t(i)].begin(), f.p[std::size_t(i)].end()}) +
              ", \"cross\": " + curve_json(f.d[std::size_t(i)]) + "}";
    text += "]}";
  }
  text += "]}";
  const Scene scene = parse_scene(text, "generated.json");
  TessellationCache cache;
  const SceneSurfaces ss = evaluate_scene(scene, 32, std::nullopt, cache, "generated.json");
  ASSERT_EQ(ss.surfaces.size(), schemes.size());
  const double size = face_size(f);
  for (std::size_t k = 0; k < schemes.size(); ++k) {
    const Reference ref = reference_of(f, schemes[k], TwistEstimate::Exact);
    const SurfaceMesh mesh = make_surface_mesh(*ss.surfaces[k].evaluator, "face");
    ASSERT_GT(mesh.positions.size(), 100u);
    double worst = 0;
    std::size_t checked = 0;
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
      bool vertex = false;
      for (const Vec2& v : ref.v) vertex = vertex || glm::length(mesh.params[i] - v) < 1e-12;
      if (vertex) continue;
      worst = std::max(worst, glm::length(mesh.positions[i] -
                                          ref.eval(schemes[k], mesh.params[i], ref.central)) /
                                  size);
      ++checked;
    }
    EXPECT_LT(worst, 1e-12) << ribbon_scheme_name(schemes[k]);
    std::printf(
        "[ generated ] seven sides from a file, %-18s %zu mesh vertices within %.3g relative\n",
        std::string(ribbon_scheme_name(schemes[k])).c_str(), checked, worst);
  }
}

}  // namespace
}  // namespace pl
