// The rational weight a / (a + b) of a Gregory twin, a and b the twins' "distance" jets (both
// >= 0 on the domain, vanishing together only at the twins' corner).
#pragma once

#include <cmath>

#include "core/math/jet.hpp"

namespace pl {

// Below this a + b is treated as the corner itself: the limit of the weight does not exist
// there, and the guarded 1/2 (zero derivatives) keeps the paired weights summing to one. The
// blended basis functions vanish to second order at the corner, so the guard changes values by
// at most ~1e-60 and first derivatives by ~1e-30, far below rounding.
inline constexpr double kTwinCornerGuard = 1e-30;

inline Jet twin_weight(const Jet& a, const Jet& b) {
  const Jet s = a + b;
  if (std::fabs(s.f) < kTwinCornerGuard) return Jet(0.5);
  return a / s;
}

}  // namespace pl
