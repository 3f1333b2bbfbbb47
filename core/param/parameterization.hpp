// The parameterization of a multi-sided patch, as the Generalized Bézier papers build it:
// generalized barycentric coordinates lambda_i of the polygon's vertices and, for every side i
// (from vertex i-1 to vertex i), the local parameters
//   s_i = lambda_i / (lambda_{i-1} + lambda_i)   (0 at vertex i-1, 1 at vertex i),
//   h_i = 1 - lambda_{i-1} - lambda_i            (0 on side i),
// all as Jets (exact first and second (u, v) derivatives). The implementations differ in their
// coordinates: Wachspress (convex polygons, the central-point GB patch; wachspress.hpp) and
// mean value (any simple polygon, the independent-ribbon GB patch; mean_value.hpp).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "core/math/jet.hpp"
#include "core/math/scratch.hpp"
#include "core/math/vec.hpp"

namespace pl {

// Bit i selects side i (at most 64 sides).
using SideMask = uint64_t;
inline constexpr SideMask kAllSides = ~SideMask{0};

class Parameterization {
 public:
  virtual ~Parameterization() = default;

  int sides() const { return static_cast<int>(vertices_.size()); }
  const std::vector<Vec2>& vertices() const { return vertices_; }
  const Vec2& vertex(int i) const { return vertices_[wrap(i)]; }
  int wrap(int i) const {
    const int n = sides();
    return ((i % n) + n) % n;
  }

  // lambda, s and h at x (not a vertex of the polygon). Each span has sides() entries, or is
  // empty to skip that output; s and h are written only for the sides whose bit is set in
  // `sides` (the others are left untouched).
  virtual void evaluate(Vec2 x, std::span<Jet> lambda, std::span<Jet> s, std::span<Jet> h,
                        SideMask sides = kAllSides) const = 0;

 protected:
  explicit Parameterization(std::vector<Vec2> vertices) : vertices_(std::move(vertices)) {}
  Parameterization(const Parameterization&) = default;
  Parameterization& operator=(const Parameterization&) = default;

  std::vector<Vec2> vertices_;
};

// out[i] = the sum of v[j] over every j but i-1 and i, for the sides whose bit is set: h_i
// (with v the coordinates, or weights proportional to them) as the sum of the coordinates off
// side i keeps full relative accuracy near side i, where 1 - lambda_{i-1} - lambda_i would
// cancel (the GB corner weights divide h's by each other). A few sides are summed directly,
// many through prefix and suffix sums: O(n) for all sides together. J: Jet or JetLanesOf<V>;
// N >= n + 1.
// With `scale` given, out[i] is that sum times *scale (weights over their total: h itself).
template <int N, class J>
[[gnu::always_inline]] inline void sums_off_side(int n, const J* v, J* out, SideMask sides,
                                                 const J& zero, const J* scale = nullptr) {
  const auto put = [scale](J& o, const J& x) { o = scale ? product(x, *scale) : x; };
  const SideMask all = n >= 64 ? kAllSides : (SideMask{1} << n) - 1;
  const int count = __builtin_popcountll(sides & all);
  if (count * (n - 2) <= 4 * n) {
    for (int i = 0; i < n; ++i) {
      if (!(sides >> i & 1u)) continue;
      const int prev = i == 0 ? n - 1 : i - 1;
      J rest = zero;  // a local, not out[i]: out may alias v as far as the compiler knows
      for (int j = 0; j < n; ++j)
        if (j != prev && j != i) rest = sum(rest, v[j]);
      put(out[i], rest);
    }
    return;
  }
  Scratch<J, N> prefix, suffix;  // prefix[k] = v[0] + .. + v[k-1], suffix[k] = v[k] + .. + v[n-1]
  prefix[0] = zero;
  for (int k = 0; k < n; ++k) prefix[k + 1] = sum(prefix[k], v[k]);
  suffix[n] = zero;
  for (int k = n - 1; k >= 0; --k) suffix[k] = sum(suffix[k + 1], v[k]);
  for (int i = 1; i < n; ++i)
    if (sides >> i & 1u) put(out[i], sum(prefix[i - 1], suffix[i + 1]));
  if (sides & 1u) {  // side 0 leaves out v[n-1] and v[0]: the middle run v[1] .. v[n-2]
    J rest = zero;
    for (int j = 1; j < n - 1; ++j) rest = sum(rest, v[j]);
    put(out[0], rest);
  }
}

}  // namespace pl
