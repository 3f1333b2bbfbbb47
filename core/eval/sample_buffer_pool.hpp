// The storage of an evaluator's samples, and a pool that keeps the storage of evaluators that are
// gone for the next ones of the same size.
//
// Why: a fresh million-sample evaluator spent more time getting its 208 MB (page faults, zeroing,
// then unmapping it again when dropped) than evaluating the patch into them: 2 cores, 4 KB pages,
// ~4 us a fault. A caller that evaluates the same surfaces again and again (a Python script's
// Scene.evaluate in a loop) drops one result before asking for the next; with a pool the next one
// is written into the same, already mapped storage, as PatchEvaluator::evaluate_all writes into
// its own. Reused storage is overwritten entirely (Patch::evaluate_many and
// differential_geometry_many write every field), so it needs no clearing.
#pragma once

#include <cstddef>
#include <cstdint>
#include <mutex>
#include <vector>

#include "core/geometry/differential_geometry.hpp"
#include "core/patch/surface_jet.hpp"

namespace pl {

// What an evaluator keeps of each sample.
enum class SampleStorage {
  // The surface jet (position and first and second derivatives, 144 bytes) and the geometry:
  // a control-point move is an axpy with the point's influence column (a drag's view).
  Jets,
  // The position and the geometry only (88 instead of 208 bytes): what drawing and analysis
  // read. A control-point move evaluates the patch again (a view at rest, which a drag's release
  // moves once).
  Compact,
};

// One evaluator's per-sample arrays: jets (Jets storage) or positions (Compact), and geometry.
struct SampleBuffers {
  std::vector<SurfaceJet> jets;
  std::vector<Vec3> positions;
  std::vector<SurfaceGeometry> geometry;

  std::size_t samples() const { return geometry.size(); }
  SampleStorage storage() const {
    return jets.empty() ? SampleStorage::Compact : SampleStorage::Jets;
  }
  std::size_t bytes() const {
    return jets.size() * sizeof(SurfaceJet) + positions.size() * sizeof(Vec3) +
           geometry.size() * sizeof(SurfaceGeometry);
  }
  // Buffers of n samples in `storage`, new (value-initialised).
  static SampleBuffers fresh(std::size_t n, SampleStorage storage);
};

// Dropped buffers kept for reuse, at most `budget` bytes of them (the least recently given back go
// first). Thread-safe. Only buffers of at least kMinSamples are kept: smaller ones cost the
// allocator little, and a scene of thousands of small faces would fill the pool for no gain.
class SampleBufferPool {
 public:
  static constexpr std::size_t kMinSamples = 4096;
  static constexpr std::size_t kDefaultBudget = std::size_t(1) << 30;

  explicit SampleBufferPool(std::size_t budget = kDefaultBudget) : budget_(budget) {}

  // Kept buffers of exactly n samples in `storage` (their old contents), else fresh ones.
  SampleBuffers take(std::size_t n, SampleStorage storage);
  // Keeps b for a later take (or frees it: too small, or over the budget).
  void give(SampleBuffers&& b);

  std::size_t kept_bytes() const;
  std::size_t kept_count() const;

 private:
  struct Kept {
    SampleBuffers buffers;
    uint64_t given = 0;  // when it was given back (a counter)
  };
  mutable std::mutex mutex_;
  std::vector<Kept> kept_;
  std::size_t bytes_ = 0;
  std::size_t budget_;
  uint64_t clock_ = 0;
};

}  // namespace pl
