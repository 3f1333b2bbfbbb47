// Basis blocks shared between patches: the basis functions of a patch type that is linear in its
// control points depend on its domain, its layout (degrees, layers) and the domain points alone.
// A curve network's convex GB faces of n sides all have the regular n-gon and, at one density,
// the same tessellation, so one block of basis values serves every face: its evaluation becomes
// S = sum_k phi_k C_k, a few hundred multiply-adds a sample instead of the coordinates, powers
// and blends.
//
// A block is kept only when a second patch asks for it (a face with a domain of its own would
// build it for nothing), within a memory budget (the least recently used blocks go first); a
// block too large for the budget is never kept. A caller without a block evaluates the same basis
// itself, so that its results do not depend on what was evaluated before it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "core/math/jet.hpp"
#include "core/math/vec.hpp"

namespace pl {

// The basis at each of `xs` (row i: the `width` basis functions at xs[i]), kept under `layout`
// (the patch's type, domain and degrees: whatever its basis depends on besides the points) and
// the points themselves. None when this block is asked for the first time, or would not fit.
// `build(x, row)` fills one row. Thread-safe.
std::shared_ptr<const std::vector<Jet>> shared_basis_block(
    const std::string& layout, std::span<const Vec2> xs, std::size_t width,
    const std::function<void(Vec2, std::span<Jet>)>& build);

// While one lives, this thread neither finds nor keeps blocks: its evaluations are those of a patch
// on its own (a gb-ribbons patch then runs its SIMD form, gb_ribbon_patch.hpp), and so are the
// chunks of a PatchEvaluator or evaluate_scene() it starts, on whichever thread they run.
// Throughput figures use it, so that they compare schemes, not a cache that only some of them
// have (evaluating the same face again would otherwise time the kept basis).
class SharedBasisBypass {
 public:
  SharedBasisBypass();
  ~SharedBasisBypass();
  SharedBasisBypass(const SharedBasisBypass&) = delete;
  SharedBasisBypass& operator=(const SharedBasisBypass&) = delete;

 private:
  bool was_;
};

// Whether a SharedBasisBypass lives on this thread.
bool shared_basis_bypassed();

// How many blocks are kept now, and their bytes (tests, benchmarks).
struct SharedBasisUse {
  std::size_t blocks = 0, bytes = 0;
};
SharedBasisUse shared_basis_use();

// The memory the kept blocks may take, in bytes.
inline constexpr std::size_t kSharedBasisBudget = std::size_t(64) << 20;

}  // namespace pl
