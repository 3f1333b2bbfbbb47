// Finds the sides of four-sided pieces that are the same curve in space: sampled at
// kSideParams, two sides match when every sample agrees within eps, forwards (t <-> t) or
// backwards (t <-> 1 - t). Sorting by the middle sample keeps it O(n log n).
#pragma once

#include <array>
#include <vector>

#include "core/math/vec.hpp"

namespace pl {

inline constexpr std::array<double, 5> kSideParams{0.0, 0.21, 0.5, 0.79, 1.0};
using SideSamples = std::array<Vec3, kSideParams.size()>;

struct SideRef {
  int piece = -1, side = -1;
};

struct SideGroup {
  std::vector<SideRef> members;  // members[0] is the reference direction
  std::vector<bool> reversed;    // members[k] runs opposite to members[0]
};

// sides[i]: the samples of side i (any order); refs[i] names it. Every side is in exactly one
// group (singletons included).
std::vector<SideGroup> match_sides(const std::vector<SideSamples>& sides,
                                   const std::vector<SideRef>& refs, double eps);

}  // namespace pl
