// Jets of several samples at once, one sample per SIMD lane (GCC vector extensions), for batched
// evaluation: the same formulas as jet.hpp, so a lane computes what the scalar Jet computes (the
// core is built with -ffp-contract=off, so the ISA-specific clones form no FMAs either).
// Lanes come in two widths, each native to the ISA it is compiled for: 8 doubles (one AVX-512
// register) in functions marked PATCHLAB_LANES_WIDE, called where wide_lanes() holds, and 4 (one
// AVX2 register, two SSE2 ones in the portable build) in functions marked PATCHLAB_LANES_CLONES.
// Measured on the GB patch: 8 lanes run ~30% faster than 4 with AVX-512 but 7x slower with AVX2
// (GCC lowers vectors wider than the ISA through memory), and 4 lanes gain nothing from AVX-512.
//
// Functions that use lanes are compiled for several ISAs with PATCHLAB_LANES_CLONES (GCC function
// multiversioning, chosen at load time by the CPU); every helper here is always_inline so it is
// compiled into each clone, and a bare Lane is never passed or returned by value (its ABI depends
// on the ISA, and GCC warns about that even for inlined functions).
#pragma once

#include <atomic>
#include <cmath>
#include <type_traits>

#include "core/math/jet.hpp"

namespace pl {

template <int W>
struct LaneType {
  typedef double type __attribute__((vector_size(W * sizeof(double))));
};
template <int W>
using LaneOf = typename LaneType<W>::type;
inline constexpr int kLanes = 4, kWideLanes = 8;
using Lane = LaneOf<kLanes>;
using WideLane = LaneOf<kWideLanes>;

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__)
#define PATCHLAB_LANES_CLONES __attribute__((target_clones("arch=x86-64-v3", "default")))
#define PATCHLAB_LANES_WIDE __attribute__((target("arch=x86-64-v4")))
// Whether this CPU runs PATCHLAB_LANES_WIDE code (x86-64-v4: AVX-512 F, BW, CD, DQ, VL over v3).
inline bool cpu_has_wide_lanes() {
  static const bool wide =
      __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512bw") &&
      __builtin_cpu_supports("avx512cd") && __builtin_cpu_supports("avx512dq") &&
      __builtin_cpu_supports("avx512vl") && __builtin_cpu_supports("avx2") &&
      __builtin_cpu_supports("fma") && __builtin_cpu_supports("bmi2");
  return wide;
}
#else
#define PATCHLAB_LANES_CLONES
#define PATCHLAB_LANES_WIDE
inline bool cpu_has_wide_lanes() {
  return false;
}
#endif
// Set by tests and benchmarks to run the kLanes forms on a CPU that has the wide ones.
inline std::atomic<bool> narrow_lanes_only{false};
inline bool wide_lanes() {
  return !narrow_lanes_only.load(std::memory_order_relaxed) && cpu_has_wide_lanes();
}
#define PATCHLAB_LANES_INLINE [[gnu::always_inline]] inline

// A jet per lane; V = Lane or WideLane.
template <class V>
struct JetLanesOf {
  V f, fu, fv, fuu, fuv, fvv;
};
using JetLanes = JetLanesOf<Lane>;
using WideJetLanes = JetLanesOf<WideLane>;

template <class V>
PATCHLAB_LANES_INLINE JetLanesOf<V> constant_lanes(double c) {
  const V z{};
  return {z + c, z, z, z, z, z};
}

template <class V>
PATCHLAB_LANES_INLINE void add_to(JetLanesOf<V>& a, const JetLanesOf<V>& b) {
  a.f += b.f, a.fu += b.fu, a.fv += b.fv, a.fuu += b.fuu, a.fuv += b.fuv, a.fvv += b.fvv;
}

template <class V>
PATCHLAB_LANES_INLINE JetLanesOf<V> sum(const JetLanesOf<V>& a, const JetLanesOf<V>& b) {
  return {a.f + b.f, a.fu + b.fu, a.fv + b.fv, a.fuu + b.fuu, a.fuv + b.fuv, a.fvv + b.fvv};
}

template <class V>
PATCHLAB_LANES_INLINE JetLanesOf<V> scaled(const JetLanesOf<V>& a, double s) {
  return {a.f * s, a.fu * s, a.fv * s, a.fuu * s, a.fuv * s, a.fvv * s};
}

// a - b as a + (-b): the same number as Jet's a - b, component by component.
template <class V>
PATCHLAB_LANES_INLINE JetLanesOf<V> difference(const JetLanesOf<V>& a, const JetLanesOf<V>& b) {
  return {a.f - b.f, a.fu - b.fu, a.fv - b.fv, a.fuu - b.fuu, a.fuv - b.fuv, a.fvv - b.fvv};
}

// a times a different factor in each lane.
template <class V>
PATCHLAB_LANES_INLINE JetLanesOf<V> scaled(const JetLanesOf<V>& a, const V& s) {
  return {a.f * s, a.fu * s, a.fv * s, a.fuu * s, a.fuv * s, a.fvv * s};
}

template <class V>
PATCHLAB_LANES_INLINE JetLanesOf<V> product(const JetLanesOf<V>& a, const JetLanesOf<V>& b) {
  return jet_product(a, b);
}

// Code written once for one sample (T = double, jets are Jet) and for a block of samples
// (T = Lane or WideLane, jets are JetLanesOf<T>): JetOf<T> is the jet type, constant_jet<T> a
// constant, lane(a, b) the jet of sample b; product, sum, scaled, add_to, reciprocal and chain
// above have Jet forms in jet.hpp, and reciprocal(LinearLanesOf<T>) serves both.
template <class T>
struct JetType {
  using type = JetLanesOf<T>;
};
template <>
struct JetType<double> {
  using type = Jet;
};
template <class T>
using JetOf = typename JetType<T>::type;

// A function linear in (u, v): value per lane, gradient shared by every lane.
template <class V>
struct LinearLanesOf {
  V f;
  double fu, fv;
};

template <class V>
PATCHLAB_LANES_INLINE JetLanesOf<V> times_linear(const JetLanesOf<V>& a,
                                                 const LinearLanesOf<V>& l) {
  return jet_times_linear(a, l);
}

template <class V>
PATCHLAB_LANES_INLINE JetLanesOf<V> chain(const JetLanesOf<V>& a, const V& d0, const V& d1,
                                          const V& d2) {
  return jet_chain(a, d0, d1, d2);
}

template <class V>
PATCHLAB_LANES_INLINE JetLanesOf<V> reciprocal(const JetLanesOf<V>& a) {
  const V r = 1.0 / a.f;
  return chain(a, r, -r * r, 2 * r * r * r);
}

// 1 / l for a linear l (a Jet for V = double).
template <class V>
PATCHLAB_LANES_INLINE JetOf<V> reciprocal(const LinearLanesOf<V>& l) {
  const V r = 1.0 / l.f, d1 = -r * r, d2 = 2 * r * r * r;
  return {r, d1 * l.fu, d1 * l.fv, d2 * l.fu * l.fu, d2 * l.fu * l.fv, d2 * l.fv * l.fv};
}

template <class V>
PATCHLAB_LANES_INLINE Jet lane(const JetLanesOf<V>& a, int b) {
  return {a.f[b], a.fu[b], a.fv[b], a.fuu[b], a.fuv[b], a.fvv[b]};
}

template <class T>
PATCHLAB_LANES_INLINE JetOf<T> constant_jet(double c) {
  if constexpr (std::is_same_v<T, double>)
    return Jet(c);
  else
    return constant_lanes<T>(c);
}

PATCHLAB_LANES_INLINE Jet lane(const Jet& a, int) {
  return a;
}

// The samples a number type carries: 1 for double, one per lane for a lane type.
template <class T>
inline constexpr int lane_count = sizeof(T) / sizeof(double);

// Value b of a lane type, or the double itself; and its setter.
template <class T>
PATCHLAB_LANES_INLINE double lane_value(const T& x, int b) {
  if constexpr (std::is_same_v<T, double>)
    return x;
  else
    return x[b];
}
template <class T>
PATCHLAB_LANES_INLINE void set_lane_value(T& x, int b, double value) {
  if constexpr (std::is_same_v<T, double>)
    x = value;
  else
    x[b] = value;
}

// Sets the jet of sample b (for Jet, the jet itself).
template <class J>
PATCHLAB_LANES_INLINE void set_lane(J& a, int b, const Jet& value) {
  set_lane_value(a.f, b, value.f), set_lane_value(a.fu, b, value.fu);
  set_lane_value(a.fv, b, value.fv), set_lane_value(a.fuu, b, value.fuu);
  set_lane_value(a.fuv, b, value.fuv), set_lane_value(a.fvv, b, value.fvv);
}

// A function linear in (u, v) as the jet of one sample (LinearLanesOf<double> is its scalar form).
template <class T>
PATCHLAB_LANES_INLINE JetOf<T> linear_jet(const LinearLanesOf<T>& l) {
  const T z{};
  return {l.f, z + l.fu, z + l.fv, z, z, z};
}

// sqrt(a) with the derivatives Jet's sqrt() gives, for a Jet or a JetLanesOf.
template <class J>
PATCHLAB_LANES_INLINE J jet_sqrt(const J& a) {
  auto r = a.f;
  for (int b = 0; b < lane_count<decltype(r)>; ++b)
    set_lane_value(r, b, std::sqrt(lane_value(r, b)));
  return chain(a, r, 0.5 / r, -0.25 / (r * a.f));
}

// a where m holds, else b, sample by sample (m: a bool for one sample, a lane comparison's mask).
template <class M, class J>
PATCHLAB_LANES_INLINE J select_jet(const M& m, const J& a, const J& b) {
  return {m ? a.f : b.f,     m ? a.fu : b.fu,   m ? a.fv : b.fv,
          m ? a.fuu : b.fuu, m ? a.fuv : b.fuv, m ? a.fvv : b.fvv};
}

}  // namespace pl
