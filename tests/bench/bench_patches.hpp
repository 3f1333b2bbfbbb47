// The patches the benchmarks share: the bicubic of bezier_bench.cpp, the GB patch of gb_bench.cpp.
#pragma once

#include <memory>

#include "core/patch/bezier_patch.hpp"
#include "core/patch/gb/gb_patch.hpp"

namespace pl::bench {

// A bicubic Bézier patch over the unit square with random heights (fixed seed).
std::shared_ptr<BezierPatch> random_bicubic();
// cagd86 from the repository's GB test data (5 sides, degree 5); throws when it is missing.
std::shared_ptr<GBPatch> cagd86();

}  // namespace pl::bench
