#include "core/patch/transfinite/polygon_parameters.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/patch/transfinite/ribbon_set.hpp"

namespace pl::transfinite {

namespace {
constexpr double kEps = 1e-8;
}

PolygonParameters::PolygonParameters(std::vector<Vec2> vertices, Vec2 centre)
    : v_(std::move(vertices)), centre_(centre) {
  const int n = size();
  if (n < 3) throw std::invalid_argument("a polygon domain needs at least 3 vertices");
  for (int i = 0; i < n; ++i) {
    const Vec2 du = vertex(i) - vertex(i - 1);
    Vec2 dv(du.y, -du.x);
    if (glm::dot(centre_ - vertex(i), dv) < 0) dv = -dv;
    du_.push_back(du);
    dv_.push_back(dv);
  }
  for (int i = 0; i < n; ++i) {
    double m = 0;
    for (int j = 0; j < n; ++j) m = std::max(m, local(i, vertex(j) - vertex(i)).y);
    parallel_scale_.push_back(1 / m);
    const Vec2 a = glm::normalize(vertex(i - 1) - vertex(i)),
               b = glm::normalize(vertex(i + 1) - vertex(i));
    sin_angle_.push_back(std::abs(cross(a, b)));
  }
}

Vec2 PolygonParameters::local(int i, Vec2 w) const {
  const Vec2& du = du_[wrap(i)];
  const double l2 = glm::dot(du, du);
  return {glm::dot(w, du) / l2, glm::dot(w, dv_[wrap(i)]) / l2};
}

std::pair<Jet, Jet> PolygonParameters::local_point(int i, const Jet& u, const Jet& v,
                                                   Vec2 origin) const {
  const Vec2& du = du_[wrap(i)];
  const Vec2& dv = dv_[wrap(i)];
  const double l2 = glm::dot(du, du);
  const Jet x = u - origin.x, y = v - origin.y;
  return {(x * du.x + y * du.y) / l2, (x * dv.x + y * dv.y) / l2};
}

Jet PolygonParameters::bilinear_s(int i, const Jet& u, const Jet& v) const {
  const Vec2 p1 = local(i, vertex(i - 2) - vertex(i - 1));
  const Vec2 p2 = local(i, vertex(i + 1) - vertex(i));
  const auto [px, py] = local_point(i, u, v, vertex(i - 1));  // linear in (u, v)
  const double a = p1.y - p2.y;
  const Jet b = px * p2.y - (px + 1.0) * p1.y + py * (p1.x - p2.x);
  const Jet c = px * p1.y - py * p1.x;
  if (std::abs(a) < kEps) {
    if (std::abs(b.f) < kEps) return Jet(0.0);
    return -c / b;
  }
  const Jet disc = b * b - 4.0 * a * c;
  const Jet root = disc.f < kEps ? Jet(0.0) : sqrt(disc);
  const Jet r1 = (-b + root) / (2 * a), r2 = (-b - root) / (2 * a);
  const Jet& s1 = r1.f >= r2.f ? r1 : r2;  // the larger root
  const Jet& s2 = r1.f >= r2.f ? r2 : r1;
  return std::max(0.0, s1.f - 1) < std::max(0.0, -s2.f) ? s1 : s2;
}

Jet PolygonParameters::bilinear_d(int i, const Jet& u, const Jet& v, const Jet& s) const {
  const double p1y = local(i, vertex(i - 2) - vertex(i - 1)).y;
  const double p2y = local(i, vertex(i + 1) - vertex(i)).y;
  const Jet py = local_point(i, u, v, vertex(i - 1)).second;
  return py / ((1.0 - s) * p1y + s * p2y);
}

SideParameters PolygonParameters::bilinear(Vec2 x) const {
  const Jet u = Jet::u(x.x), v = Jet::v(x.y);
  SideParameters out;
  for (int i = 0; i < size(); ++i) {
    out.s.push_back(bilinear_s(i, u, v));
    out.d.push_back(bilinear_d(i, u, v, out.s.back()));
  }
  return out;
}

SideParameters PolygonParameters::parallel(Vec2 x) const {
  const Jet u = Jet::u(x.x), v = Jet::v(x.y);
  SideParameters out;
  for (int i = 0; i < size(); ++i) {
    out.s.push_back(bilinear_s(i, u, v));
    out.d.push_back(local_point(i, u, v, vertex(i)).second * parallel_scale_[i]);
  }
  return out;
}

SideParameters PolygonParameters::interconnected(Vec2 x) const {
  const Jet u = Jet::u(x.x), v = Jet::v(x.y);
  SideParameters out;
  for (int i = 0; i < size(); ++i) out.s.push_back(bilinear_s(i, u, v));
  for (int i = 0; i < size(); ++i) {
    const Jet h = hermite_blend(out.s[i]);
    out.d.push_back((1.0 - out.s[wrap(i - 1)]) * h + out.s[wrap(i + 1)] * (1.0 - h));
  }
  return out;
}

std::vector<Jet> PolygonParameters::wachspress(Vec2 x) const {
  const int n = size();
  const Jet u = Jet::u(x.x), v = Jet::v(x.y);
  // Half the cross product of (x - a) and (x - b), a quadratic in (u, v).
  const auto area = [&](const Vec2& a, const Vec2& b) {
    const Jet ax = u - a.x, ay = v - a.y, bx = u - b.x, by = v - b.y;
    return (ax * by - ay * bx) * 0.5;
  };
  std::vector<Jet> A(n);
  for (int j = 0; j < n; ++j) A[j] = area(vertex(j), vertex(j + 1));
  std::vector<Jet> w(n);
  Jet sum(0.0);
  for (int i = 0; i < n; ++i) {
    const Jet B = area(vertex(i - 1), vertex(i + 1));
    Jet skip_prev(1.0), skip_this(1.0), skip_both(1.0);
    const int prev = wrap(i - 1);
    for (int j = 0; j < n; ++j) {
      if (j != prev) skip_prev = skip_prev * A[j];
      if (j != i) skip_this = skip_this * A[j];
      if (j != prev && j != i) skip_both = skip_both * A[j];
    }
    w[i] = skip_prev + skip_this - B * skip_both;
    sum += w[i];
  }
  const Jet r = reciprocal(sum);
  for (Jet& wi : w) wi = wi * r;
  return w;
}

SideParameters PolygonParameters::barycentric(Vec2 x) const {
  const int n = size();
  const std::vector<Jet> l = wachspress(x);
  SideParameters out;
  for (int i = 0; i < n; ++i) {
    const Jet& a = l[wrap(i - 1)];
    const Jet& b = l[i];
    const Jet denom = a + b;
    if (denom.f < kEps) {
      // On a domain edge sharing no vertex with side i (n >= 4) s_i has no value of its own; the
      // terms using it have zero weight and zero first derivatives there, so only its value
      // matters (in second derivatives): the limit approaching along the edge's normal.
      const auto dist = [&](int k) {  // distance of x from the line of side k
        const Vec2 a0 = vertex(k - 1), a1 = vertex(k);
        return std::abs(cross(a1 - a0, x - a0)) / glm::length(a1 - a0);
      };
      const double p = dist(i - 1), q = dist(i + 1);
      const double sa = sin_angle_[wrap(i)], sb = sin_angle_[wrap(i - 1)];
      const double den = sa * p + sb * q;
      out.s.push_back(Jet(den < kEps ? 0.0 : sa * p / den));
    } else {
      out.s.push_back(b / denom);
    }
    out.d.push_back(1.0 - denom);
  }
  return out;
}

SideParameters PolygonParameters::constrained_barycentric(Vec2 x) const {
  const int n = size();
  SideParameters bc = barycentric(x);
  SideParameters out;
  out.s = bc.s;
  for (int i = 0; i < n; ++i) {
    const Jet& d = bc.d[i];
    const Jet& s = bc.s[i];
    const Jet vals[4] = {d, 1.0 - s, 1.0 - d, s};
    // Weights proportional to value^-2, written as products of the others' squares so that they
    // stay finite where one value vanishes.
    Jet b[4];
    Jet sum(0.0);
    for (int k = 0; k < 4; ++k) {
      Jet p(1.0);
      for (int m = 0; m < 4; ++m)
        if (m != k) p = p * (vals[m] * vals[m]);
      b[k] = p;
      sum += p;
    }
    const Jet r = reciprocal(sum);
    for (Jet& bk : b) bk = bk * r;
    out.d.push_back(d * (b[0] + b[2]) + bc.s[wrap(i + 1)] * b[1] +
                    (1.0 - bc.s[wrap(i - 1)]) * b[3]);
  }
  return out;
}

}  // namespace pl::transfinite
