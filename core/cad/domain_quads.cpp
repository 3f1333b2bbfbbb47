#include "core/cad/domain_quads.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace pl {

namespace {

double cross2(Vec2 a, Vec2 b) {
  return a.x * b.y - a.y * b.x;
}

double polygon_size(const std::vector<Vec2>& P) {
  double s = 0;
  for (const Vec2& a : P)
    for (const Vec2& b : P) s = std::max(s, glm::length(a - b));
  return s;
}

// Turn at vertex i (positive: convex corner of a counter-clockwise polygon).
double turn(const std::vector<Vec2>& P, std::size_t i) {
  const std::size_t n = P.size();
  const Vec2 a = P[(i + n - 1) % n], b = P[i], c = P[(i + 1) % n];
  return cross2(b - a, c - b) / (glm::length(b - a) * glm::length(c - b));
}

bool strictly_convex(const std::vector<Vec2>& P) {
  for (std::size_t i = 0; i < P.size(); ++i)
    if (!(turn(P, i) > 1e-9)) return false;
  return true;
}

Vec2 area_centroid(const std::vector<Vec2>& P) {
  double A = 0;
  Vec2 c(0);
  for (std::size_t i = 0; i < P.size(); ++i) {
    const Vec2 a = P[i], b = P[(i + 1) % P.size()];
    const double w = cross2(a, b);
    A += w;
    c += w * (a + b);
  }
  return c / (3 * A);
}

void check_quad(const DomainQuad& q) {
  for (int k = 0; k < 4; ++k) {
    const Vec2 a = q[k], b = q[(k + 1) % 4], c = q[(k + 2) % 4];
    if (!(cross2(b - a, c - b) > 0))
      throw std::invalid_argument("the domain cannot be split into convex quadrilaterals");
  }
}

// Corners of a polygon split centrally stay below this (interior angle, degrees).
constexpr double kMaxCornerDeg = 150;

// Interior angle's supplement at vertex i: the turn in degrees (positive: convex).
double turn_deg(const std::vector<Vec2>& P, std::size_t i) {
  const std::size_t n = P.size();
  const Vec2 a = P[(i + n - 1) % n], b = P[i], c = P[(i + 1) % n];
  return std::atan2(cross2(b - a, c - b), glm::dot(b - a, c - b)) * 180 / M_PI;
}

void split_convex(const std::vector<Vec2>& P, bool keep_quads, std::vector<DomainQuad>& out,
                  bool ring = true) {
  const std::size_t n = P.size();
  if (n == 4 && keep_quads) {
    out.push_back({P[0], P[1], P[2], P[3]});
    check_quad(out.back());
    return;
  }
  const Vec2 c = area_centroid(P);
  // Corners close to straight (many sides) would make central pieces with corners close to 180
  // degrees, where a fit's normal is ill-conditioned next to a singular patch corner: a ring of
  // pieces first (two per side, between the side and the polygon shrunk halfway to the centroid,
  // which halves every corner), then the inner polygon split centrally.
  double max_turn_deg = 0;
  for (std::size_t i = 0; i < n; ++i) max_turn_deg = std::max(max_turn_deg, 180 - turn_deg(P, i));
  if (ring && max_turn_deg > kMaxCornerDeg + 1e-6) {
    std::vector<Vec2> W;
    for (const Vec2& p : P) W.push_back(c + 0.5 * (p - c));
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t j = (i + 1) % n;
      const Vec2 m = 0.5 * (P[i] + P[j]), w = 0.5 * (W[i] + W[j]);
      out.push_back({P[i], m, w, W[i]});
      check_quad(out.back());
      out.push_back({m, P[j], W[j], w});
      check_quad(out.back());
    }
    split_convex(W, false, out, false);
    return;
  }
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 next = 0.5 * (P[i] + P[(i + 1) % n]), prev = 0.5 * (P[(i + n - 1) % n] + P[i]);
    out.push_back({P[i], next, c, prev});
    check_quad(out.back());
  }
}

// Cuts P at its first reflex vertex along the bisector; returns false if P is convex.
bool cut_reflex(const std::vector<Vec2>& P, std::vector<Vec2>& A, std::vector<Vec2>& B) {
  const std::size_t n = P.size();
  for (std::size_t r = 0; r < n; ++r) {
    if (turn(P, r) > -1e-9) continue;
    const Vec2 v = P[r];
    const Vec2 d_in = glm::normalize(P[(r + n - 1) % n] - v) + glm::normalize(P[(r + 1) % n] - v);
    // At a reflex vertex the sum of the two edge directions points out of the polygon.
    const Vec2 dir = glm::length(d_in) > 1e-12
                         ? -glm::normalize(d_in)
                         : Vec2(-(P[(r + 1) % n] - v).y, (P[(r + 1) % n] - v).x);
    double best = std::numeric_limits<double>::infinity();
    std::size_t side = n;
    double at = 0;
    for (std::size_t s = 0; s < n; ++s) {
      if (s == r || (s + 1) % n == r) continue;
      const Vec2 a = P[s], e = P[(s + 1) % n] - a;
      const double den = cross2(dir, e);
      if (std::fabs(den) < 1e-14) continue;
      const double t = cross2(a - v, e) / den;    // along the ray
      const double w = cross2(a - v, dir) / den;  // along the side
      if (t > 1e-12 && w >= 0 && w <= 1 && t < best) best = t, side = s, at = w;
    }
    if (side == n) throw std::invalid_argument("a reflex corner of the domain has no cut");
    // A hit at a side's end is that vertex itself.
    const std::size_t s1 = (side + 1) % n;
    A.clear(), B.clear();
    if (at < 1e-9 || at > 1 - 1e-9) {
      const std::size_t h = at < 0.5 ? side : s1;
      for (std::size_t k = r;; k = (k + 1) % n) {
        A.push_back(P[k]);
        if (k == h) break;
      }
      for (std::size_t k = h;; k = (k + 1) % n) {
        B.push_back(P[k]);
        if (k == r) break;
      }
    } else {
      const Vec2 hit = P[side] + at * (P[s1] - P[side]);
      for (std::size_t k = r;; k = (k + 1) % n) {
        A.push_back(P[k]);
        if (k == side) break;
      }
      A.push_back(hit);
      B.push_back(hit);
      for (std::size_t k = s1;; k = (k + 1) % n) {
        B.push_back(P[k]);
        if (k == r) break;
      }
    }
    return true;
  }
  return false;
}

void split(const std::vector<Vec2>& P, bool keep_quads, std::vector<DomainQuad>& out, int depth) {
  if (depth > 64) throw std::invalid_argument("the domain has too many reflex corners to split");
  std::vector<Vec2> A, B;
  if (!cut_reflex(P, A, B)) {
    if (!strictly_convex(P))
      throw std::invalid_argument("the domain has a straight corner and cannot be split");
    split_convex(P, keep_quads, out);
    return;
  }
  split(A, false, out, depth + 1);
  split(B, false, out, depth + 1);
}

}  // namespace

std::vector<Vec2> domain_polygon(const Domain& domain) {
  std::vector<Vec2> P;
  for (int s = 0; s < domain.side_count(); ++s) P.push_back(domain.side_point(s, 0.0));
  return P;
}

std::vector<DomainQuad> split_into_quads(const std::vector<Vec2>& P) {
  if (P.size() < 3) throw std::invalid_argument("a domain needs at least 3 corners");
  if (!(polygon_size(P) > 0)) throw std::invalid_argument("the domain is a point");
  std::vector<DomainQuad> out;
  split(P, true, out, 0);
  return out;
}

Vec2 quad_point(const DomainQuad& q, Vec2 x) {
  return (1 - x.x) * (1 - x.y) * q[0] + x.x * (1 - x.y) * q[1] + x.x * x.y * q[2] +
         (1 - x.x) * x.y * q[3];
}
Vec2 quad_du(const DomainQuad& q, Vec2 x) {
  return (1 - x.y) * (q[1] - q[0]) + x.y * (q[2] - q[3]);
}
Vec2 quad_dv(const DomainQuad& q, Vec2 x) {
  return (1 - x.x) * (q[3] - q[0]) + x.x * (q[2] - q[1]);
}

}  // namespace pl
