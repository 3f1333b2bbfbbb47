// Jets of several samples at once, one sample per SIMD lane (GCC vector extensions), for batched
// evaluation: the same formulas as jet.hpp, so a lane computes what the scalar Jet computes (the
// core is built with -ffp-contract=off, so the ISA-specific clones form no FMAs either).
// Lane is 4 doubles, one AVX2 register (two SSE2 ones in the portable build). Measured on the
// GB patch: 8 lanes ran 30% faster as native AVX-512 registers but 7x slower on AVX2 (GCC lowers
// vectors wider than the ISA through memory), and an AVX-512 clone of 4 lanes gained nothing.
//
// Functions that use lanes are compiled for several ISAs with PATCHLAB_LANES_CLONES (GCC function
// multiversioning, chosen at load time by the CPU); every helper here is always_inline so it is
// compiled into each clone, and a bare Lane is never passed or returned by value (its ABI depends
// on the ISA, and GCC warns about that even for inlined functions).
#pragma once

#include "core/math/jet.hpp"

namespace pl {

inline constexpr int kLanes = 4;
using Lane = double __attribute__((vector_size(kLanes * sizeof(double))));

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__)
#define PATCHLAB_LANES_CLONES __attribute__((target_clones("arch=x86-64-v3", "default")))
#else
#define PATCHLAB_LANES_CLONES
#endif
#define PATCHLAB_LANES_INLINE [[gnu::always_inline]] inline

struct JetLanes {
  Lane f, fu, fv, fuu, fuv, fvv;
};

PATCHLAB_LANES_INLINE JetLanes constant_lanes(double c) {
  const Lane z{};
  return {z + c, z, z, z, z, z};
}

PATCHLAB_LANES_INLINE void add_to(JetLanes& a, const JetLanes& b) {
  a.f += b.f, a.fu += b.fu, a.fv += b.fv, a.fuu += b.fuu, a.fuv += b.fuv, a.fvv += b.fvv;
}

PATCHLAB_LANES_INLINE JetLanes sum(const JetLanes& a, const JetLanes& b) {
  return {a.f + b.f, a.fu + b.fu, a.fv + b.fv, a.fuu + b.fuu, a.fuv + b.fuv, a.fvv + b.fvv};
}

PATCHLAB_LANES_INLINE JetLanes scaled(const JetLanes& a, double s) {
  return {a.f * s, a.fu * s, a.fv * s, a.fuu * s, a.fuv * s, a.fvv * s};
}

PATCHLAB_LANES_INLINE JetLanes product(const JetLanes& a, const JetLanes& b) {
  return jet_product(a, b);
}

// A function linear in (u, v): value per lane, gradient shared by every lane.
struct LinearLanes {
  Lane f;
  double fu, fv;
};

PATCHLAB_LANES_INLINE JetLanes times_linear(const JetLanes& a, const LinearLanes& l) {
  return jet_times_linear(a, l);
}

PATCHLAB_LANES_INLINE JetLanes chain(const JetLanes& a, const Lane& d0, const Lane& d1,
                                     const Lane& d2) {
  return jet_chain(a, d0, d1, d2);
}

PATCHLAB_LANES_INLINE JetLanes reciprocal(const JetLanes& a) {
  const Lane r = 1.0 / a.f;
  return chain(a, r, -r * r, 2 * r * r * r);
}

// 1 / l for a linear l.
PATCHLAB_LANES_INLINE JetLanes reciprocal(const LinearLanes& l) {
  const Lane r = 1.0 / l.f, d1 = -r * r, d2 = 2 * r * r * r;
  return {r, d1 * l.fu, d1 * l.fv, d2 * l.fu * l.fu, d2 * l.fu * l.fv, d2 * l.fv * l.fv};
}

PATCHLAB_LANES_INLINE Jet lane(const JetLanes& a, int b) {
  return {a.f[b], a.fu[b], a.fv[b], a.fuu[b], a.fuv[b], a.fvv[b]};
}

}  // namespace pl
