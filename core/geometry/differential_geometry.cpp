#include "core/geometry/differential_geometry.hpp"

#include <algorithm>
#include <cassert>
#include <cfloat>
#include <cmath>
#include <utility>

#ifdef __SSE2__
#include <emmintrin.h>
#endif

// Quad (two SSE2 registers) is passed and returned by value only between always-inlined
// functions of this file, so the ABI GCC warns about never applies.
#pragma GCC diagnostic ignored "-Wpsabi"

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

namespace {
// The batched form takes four samples at a time in two SSE2 registers per number, in the portable
// build: AVX2 and AVX-512 clones, and pairs, measured slower (gathering from the jets' layout
// costs more there than the wider arithmetic saves).
constexpr int kQuad = 4;
using Quad = double __attribute__((vector_size(kQuad * sizeof(double))));

// The curvature formulas as a template over the number type, so that the batched form computes
// the one-sample numbers in every lane: T = double or Quad (then `regular` is a lane mask).
template <class T>
struct V3 {
  T x, y, z;
};
template <class T>
[[gnu::always_inline]] inline T dot(const V3<T>& a, const V3<T>& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;  // glm's order
}
template <class T>
[[gnu::always_inline]] inline V3<T> cross(const V3<T>& a, const V3<T>& b) {
  return {a.y * b.z - b.y * a.z, a.z * b.x - b.z * a.x, a.x * b.y - b.x * a.y};  // glm's order
}
[[gnu::always_inline]] inline double square_root(double x) {
  return std::sqrt(x);
}
[[gnu::always_inline]] inline Quad square_root(const Quad& x) {
#ifdef __SSE2__
  // std::sqrt per lane would keep its errno branch and stay scalar.
  using Half = double __attribute__((vector_size(16)));
  const Half lo = _mm_sqrt_pd(Half{x[0], x[1]}), hi = _mm_sqrt_pd(Half{x[2], x[3]});
  return Quad{lo[0], lo[1], hi[0], hi[1]};
#else
  return Quad{std::sqrt(x[0]), std::sqrt(x[1]), std::sqrt(x[2]), std::sqrt(x[3])};
#endif
}
[[gnu::always_inline]] inline double non_negative(double x) {
  return std::max(0.0, x);
}
[[gnu::always_inline]] inline Quad non_negative(const Quad& x) {
  return x > 0 ? x : Quad{};
}

template <class T>
struct Curvatures {
  V3<T> normal;
  T gaussian, mean, kmin, kmax;
  // The normal is defined; else the rest is meaningless. The curvatures of a regular sample may
  // still overflow (second derivatives huge against the first): see finite_curvatures.
  decltype(T{} > T{}) regular;
};

template <class T>
[[gnu::always_inline]] inline Curvatures<T> curvatures(const V3<T>& su, const V3<T>& sv,
                                                       const V3<T>& suu, const V3<T>& suv,
                                                       const V3<T>& svv) {
  Curvatures<T> g;
  const V3<T> c = cross(su, sv);
  const T det = dot(c, c);  // EG - F^2 = |Su x Sv|^2, computed directly for accuracy
  const T E = dot(su, su), F = dot(su, sv), G = dot(sv, sv);
  // Squared lengths compared: no square roots on the hot path of every drag update.
  // A subnormal det (a surface of size 1e-80) has lost its digits: rescaled_geometry takes it.
  g.regular = (det > kSingularSine * kSingularSine * (E * G)) & (det >= DBL_MIN) & (det - det == 0);
  const T scale = 1.0 / square_root(det);
  const V3<T> n{c.x * scale, c.y * scale, c.z * scale};
  const T L = dot(suu, n), M = dot(suv, n), N = dot(svv, n);
  g.normal = n;
  const T inv = 1.0 / det;
  g.gaussian = (L * N - M * M) * inv;
  g.mean = (E * N - 2 * F * M + G * L) * (0.5 * inv);
  // (k_max - k_min)^2 = (a - d)^2 + 4 b c for the shape operator W = I^-1 II = [[a, b], [c, d]]:
  // each term vanishes at an umbilic with its own rounding (about eps k), where H^2 - K subtracts
  // two numbers of size k^2 and kept only half the digits of k_max - k_min (3.9e-8 relative on a
  // sphere). Each entry is scaled by 1 / det before it is squared, so nothing overflows or
  // underflows that H itself does not.
  const T a_d = (G * L - E * N) * inv, w_b = (G * M - F * N) * inv, w_c = (E * M - F * L) * inv;
  const T disc = 0.5 * square_root(non_negative(a_d * a_d + 4 * w_b * w_c));
  g.kmin = g.mean - disc;
  g.kmax = g.mean + disc;
  return g;
}

// Whether a regular sample's curvatures are all finite, from one sum: kmin <= H <= kmax, so the
// sum is finite only if K, H, kmin and kmax are (a sum of finite terms that overflows only sends
// the sample to rescaled_geometry, which tests each). Tested per sample where the geometry is
// stored: folded into the lane mask of curvatures() it cost a third of the batched geometry, a
// tenth of a drag update (measured).
[[gnu::always_inline]] inline bool finite_curvatures(double gaussian, double kmin, double kmax) {
  return std::isfinite(gaussian + kmin + kmax);
}

V3<double> v3(const Vec3& a) {
  return {a.x, a.y, a.z};
}
}  // namespace

namespace {
// Where the direct formulas fail, the surface scaled by 1/m (m the largest first-derivative
// component): |Su x Sv|^2 is a fourth power of lengths, which overflows for a surface of size
// 1e77 and underflows for one of size 1e-77 although its normal is well defined. The scaled
// surface has the same normal, its curvatures are m times (K m^2 times) the true ones. Called only
// for the samples the direct formulas reject, so the hot path is unchanged; a truly singular
// sample (Su x Sv = 0) stays singular.
SurfaceGeometry rescaled_geometry(const SurfaceJet& s) {
  const double m = std::max({std::fabs(s.su.x), std::fabs(s.su.y), std::fabs(s.su.z),
                             std::fabs(s.sv.x), std::fabs(s.sv.y), std::fabs(s.sv.z)});
  if (!(m > 0) || !std::isfinite(m)) return {};
  const double r = 1.0 / m;
  if (!std::isfinite(r)) return {};
  const Curvatures<double> c =
      curvatures(v3(s.su * r), v3(s.sv * r), v3(s.suu * r), v3(s.suv * r), v3(s.svv * r));
  if (!c.regular) return {};
  SurfaceGeometry g{{c.normal.x, c.normal.y, c.normal.z},
                    c.gaussian * r * r,
                    c.mean * r,
                    c.kmin * r,
                    c.kmax * r,
                    GeometryStatus::Regular};
  if (!std::isfinite(g.gaussian) || !std::isfinite(g.mean) || !std::isfinite(g.kmin) ||
      !std::isfinite(g.kmax))
    return {};
  return g;
}
}  // namespace

SurfaceGeometry differential_geometry(const SurfaceJet& s) {
  const Curvatures<double> c = curvatures(v3(s.su), v3(s.sv), v3(s.suu), v3(s.suv), v3(s.svv));
  if (!c.regular || !finite_curvatures(c.gaussian, c.kmin, c.kmax))
    return rescaled_geometry(s);  // Singular (zeros) if it is one
  return {{c.normal.x, c.normal.y, c.normal.z},
          c.gaussian,
          c.mean,
          c.kmin,
          c.kmax,
          GeometryStatus::Regular};
}

namespace {
// kQuad samples (fewer at the end: count) through curvatures().
void geometry_lanes(const SurfaceJet* const* in, SurfaceGeometry* const* out, int count) {
  // Lanes built in registers: lane-by-lane stores read back as one vector would stall store
  // forwarding on every block.
  V3<Quad> d[5];  // su, sv, suu, suv, svv
  Vec3 SurfaceJet::*const rows[5] = {&SurfaceJet::su, &SurfaceJet::sv, &SurfaceJet::suu,
                                     &SurfaceJet::suv, &SurfaceJet::svv};
  for (int r = 0; r < 5; ++r) {
    Quad* to[3] = {&d[r].x, &d[r].y, &d[r].z};
    for (int c = 0; c < 3; ++c) {
      const auto at = [&](int b) { return ((*in[b]).*rows[r])[c]; };
      [&]<std::size_t... B>(std::index_sequence<B...>) {
        *to[c] = Quad{at(B)...};
      }
      (std::make_index_sequence<kQuad>());
    }
  }
  const Curvatures<Quad> c = curvatures(d[0], d[1], d[2], d[3], d[4]);
  for (int b = 0; b < count; ++b)
    *out[b] = c.regular[b] && finite_curvatures(c.gaussian[b], c.kmin[b], c.kmax[b])
                  ? SurfaceGeometry{{c.normal.x[b], c.normal.y[b], c.normal.z[b]},
                                    c.gaussian[b],
                                    c.mean[b],
                                    c.kmin[b],
                                    c.kmax[b],
                                    GeometryStatus::Regular}
                  : rescaled_geometry(*in[b]);
}

template <class At>
void geometry_blocks(std::size_t count, At&& at, std::span<const SurfaceJet> s,
                     std::span<SurfaceGeometry> out) {
  const SurfaceJet* in[kQuad];
  SurfaceGeometry* to[kQuad];
  for (std::size_t first = 0; first < count; first += kQuad) {
    const int m = static_cast<int>(std::min<std::size_t>(kQuad, count - first));
    for (int b = 0; b < m; ++b) {
      const std::size_t i = at(first + b);
      in[b] = &s[i], to[b] = &out[i];
    }
    for (int b = m; b < kQuad; ++b) in[b] = in[0];  // padding lanes: any valid sample
    geometry_lanes(in, to, m);
  }
}
}  // namespace

void differential_geometry_many(std::span<const SurfaceJet> s, std::span<SurfaceGeometry> out) {
  assert(s.size() == out.size());
  geometry_blocks(
      s.size(), [](std::size_t i) { return i; }, s, out);
}

void differential_geometry_many(std::span<const SurfaceJet> s, std::span<const uint32_t> index,
                                std::span<SurfaceGeometry> out) {
  assert(s.size() == out.size());
  geometry_blocks(
      index.size(), [&](std::size_t i) { return index[i]; }, s, out);
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
