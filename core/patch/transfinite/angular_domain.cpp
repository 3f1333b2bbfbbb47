#include "core/patch/transfinite/angular_domain.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace pl::transfinite {

namespace {

// Arc length of a side on [0, 1] by four-point Gauss-Legendre, with the nine-digit constants the
// library uses (so that its domain is reproduced to rounding).
double arc_length(const UnitCurve& c) {
  constexpr double kNodes[] = {-0.861136312, -0.339981044, 0.339981044, 0.861136312};
  constexpr double kWeights[] = {0.347854845, 0.652145155, 0.652145155, 0.347854845};
  double length = 0;
  for (int k = 0; k < 4; ++k) length += glm::length(c.at((kNodes[k] + 1) / 2).d1) * kWeights[k] / 2;
  return length;
}

double cross(Vec2 a, Vec2 b) {
  return a.x * b.y - a.y * b.x;
}

bool strictly_convex(const std::vector<Vec2>& v) {
  const std::size_t n = v.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 a = v[(i + n - 1) % n], b = v[i], c = v[(i + 1) % n];
    if (!(cross(b - a, c - b) > 0)) return false;
  }
  return true;
}

}  // namespace

std::optional<std::vector<Vec2>> angular_domain(const std::vector<RibbonCurves>& sides) {
  const std::size_t n = sides.size();
  std::vector<double> length(n), angle(n);
  double angle_sum = 0, length_sum = 0;
  for (std::size_t i = 0; i < n; ++i) {
    length[i] = arc_length(sides[i].curve);
    length_sum += length[i];
    const Vec3 in = glm::normalize(sides[i].curve.at(1).d1);
    const Vec3 out = glm::normalize(sides[(i + 1) % n].curve.at(0).d1);
    angle[i] = std::acos(std::clamp(-glm::dot(in, out), -1.0, 1.0));
    angle_sum += angle[i];
  }
  if (!(angle_sum > 0) || !(length_sum > 0)) return std::nullopt;
  // The open chain: side 0 along +x from the origin, turning by pi - (scaled corner angle).
  std::vector<Vec2> w(n);
  double direction = 0;
  w[0] = Vec2(length[0], 0);
  for (std::size_t i = 1; i < n; ++i) {
    direction += std::numbers::pi - angle[i - 1] * double(n - 2) * std::numbers::pi / angle_sum;
    w[i] = w[i - 1] + length[i] * Vec2(std::cos(direction), std::sin(direction));
  }
  // Closed: the end's gap spread over the vertices by arc length (v_{n-1} = the origin).
  std::vector<Vec2> v(n);
  double run = 0;
  for (std::size_t i = 0; i < n; ++i) {
    run += length[i];
    v[i] = w[i] - w[n - 1] * (run / length_sum);
  }
  // Into [-1, 1]^2 by the larger extent (the box started at the origin).
  Vec2 lo(0), hi(0);
  for (const Vec2& p : v) lo = glm::min(lo, p), hi = glm::max(hi, p);
  const double width = std::max(hi.x - lo.x, hi.y - lo.y);
  if (!(width > 0) || !std::isfinite(width)) return std::nullopt;
  for (Vec2& p : v) p = Vec2(-1, -1) + (p - lo) * (2 / width);
  if (!strictly_convex(v)) return std::nullopt;
  return v;
}

Vec2 angular_domain_centre(const std::vector<Vec2>& v) {
  const std::size_t n = v.size();
  Vec2 c(0);
  double total = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double here = glm::length(v[i] - v[(i + n - 1) % n]);
    const double next = glm::length(v[(i + 1) % n] - v[i]);
    c += v[i] * (here + next);
    total += here;
  }
  return c / (2 * total);
}

}  // namespace pl::transfinite
