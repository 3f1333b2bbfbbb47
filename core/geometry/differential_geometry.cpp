#include "core/geometry/differential_geometry.hpp"

#include <algorithm>
#include <cmath>

namespace pl {

namespace {
// |Su x Sv| below this fraction of |Su||Sv| (sine of the angle between them) counts as singular.
constexpr double kSingularSine = 1e-12;

// Unit normal, or false where Su x Sv vanishes. Compares squared lengths to spare two square
// roots on the hot path of every drag update.
bool normal_of(const SurfaceJet& s, Vec3& n, Vec3& c, double& len2) {
  c = glm::cross(s.su, s.sv);
  len2 = glm::dot(c, c);
  const double scale2 = glm::dot(s.su, s.su) * glm::dot(s.sv, s.sv);
  if (!(len2 > kSingularSine * kSingularSine * scale2) || !(len2 > 0) || !std::isfinite(len2))
    return false;
  n = c * (1.0 / std::sqrt(len2));
  return true;
}
}  // namespace

FundamentalForms fundamental_forms(const SurfaceJet& s) {
  Vec3 n(0), c;
  double len2;
  normal_of(s, n, c, len2);
  return {glm::dot(s.su, s.su), glm::dot(s.su, s.sv), glm::dot(s.sv, s.sv),
          glm::dot(s.suu, n),   glm::dot(s.suv, n),   glm::dot(s.svv, n)};
}

SurfaceGeometry differential_geometry(const SurfaceJet& s) {
  SurfaceGeometry g;
  Vec3 n, c;
  double det;                              // EG - F^2 = |Su x Sv|^2, computed directly for accuracy
  if (!normal_of(s, n, c, det)) return g;  // Singular, zeros
  const double E = glm::dot(s.su, s.su), F = glm::dot(s.su, s.sv), G = glm::dot(s.sv, s.sv);
  const double L = glm::dot(s.suu, n), M = glm::dot(s.suv, n), N = glm::dot(s.svv, n);
  g.normal = n;
  const double inv = 1.0 / det;
  g.gaussian = (L * N - M * M) * inv;
  g.mean = (E * N - 2 * F * M + G * L) * (0.5 * inv);
  const double disc = std::sqrt(std::max(0.0, g.mean * g.mean - g.gaussian));
  g.kmin = g.mean - disc;
  g.kmax = g.mean + disc;
  g.status = GeometryStatus::Regular;
  return g;
}

PrincipalDirections principal_directions(const SurfaceJet& s) {
  PrincipalDirections d;
  const SurfaceGeometry g = differential_geometry(s);
  if (g.status != GeometryStatus::Regular) return d;
  const FundamentalForms f = fundamental_forms(s);
  // A principal direction (a, b) in the parameter plane solves (II - k I)(a, b) = 0; take the
  // better conditioned of the two rows of that singular 2x2 matrix.
  const auto direction = [&](double k) {
    const double r0a = f.L - k * f.E, r0b = f.M - k * f.F;
    const double r1a = f.M - k * f.F, r1b = f.N - k * f.G;
    double a, b;
    if (std::hypot(r0a, r0b) >= std::hypot(r1a, r1b)) {
      a = -r0b, b = r0a;
    } else {
      a = -r1b, b = r1a;
    }
    Vec3 t = a * s.su + b * s.sv;
    const double len = glm::length(t);
    if (!(len > 0)) return glm::normalize(s.su);  // umbilic: every direction is principal
    return t / len;
  };
  d.dir_min = direction(g.kmin);
  d.dir_max = glm::normalize(glm::cross(g.normal, d.dir_min));
  return d;
}

}  // namespace pl
