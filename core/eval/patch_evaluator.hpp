// Owns the samples of one patch: a (shared) tessellation, every sample's surface jet and its
// differential geometry. Moving a control point is an axpy with that point's influence column
// (docs/developing.md): only samples where phi_k is non-zero change, and only their normals
// and curvatures are recomputed.
#pragma once

#include <algorithm>
#include <cstdint>
#include <memory>
#include <new>
#include <span>
#include <string>
#include <vector>

#include "core/domain/tessellation.hpp"
#include "core/eval/sample_buffer_pool.hpp"
#include "core/geometry/differential_geometry.hpp"
#include "core/patch/patch.hpp"

namespace pl {

class PatchEvaluator {
 public:
  // Evaluates every sample at once. With a pool, the per-sample arrays are taken from it (the
  // storage of an evaluator that is gone, when one of this size is kept) and given back to it
  // when this evaluator goes.
  PatchEvaluator(std::shared_ptr<Patch> patch, std::shared_ptr<const Tessellation> tessellation,
                 SampleStorage storage = SampleStorage::Jets,
                 std::shared_ptr<SampleBufferPool> pool = nullptr);
  ~PatchEvaluator();
  PatchEvaluator(const PatchEvaluator&) = delete;
  PatchEvaluator& operator=(const PatchEvaluator&) = delete;

  const Patch& patch() const { return *patch_; }
  const Tessellation& tessellation() const { return *tessellation_; }
  SampleStorage storage() const { return storage_; }
  std::size_t sample_count() const { return geometry_.size(); }
  // Every sample's jet; empty with SampleStorage::Compact.
  const std::vector<SurfaceJet>& jets() const { return jets_; }
  const std::vector<SurfaceGeometry>& geometry() const { return geometry_; }
  // Sample i's position (either storage).
  Vec3 position(std::size_t i) const { return jets_.empty() ? positions_[i] : jets_[i].p; }
  // Whether sample i's jet and geometry are all finite numbers (either storage).
  bool finite(std::size_t i) const;
  // Increases whenever samples change, so the renderer knows what to re-upload.
  uint64_t revision() const { return revision_; }
  // An evaluator that replaces another continues its revision numbers, so a renderer that
  // remembers the old number still sees a change.
  void continue_revisions_from(uint64_t previous) { revision_ = std::max(revision_, previous + 1); }

  // Recomputes everything from the patch (the from-scratch path).
  void evaluate_all();

  // Builds (or refreshes the recency of) control point k's influence column: the one-off cost at
  // drag start. Called implicitly by move_control_point.
  void prepare_influence(std::size_t k);

  // Moves control point k to p, updating only the samples it influences. Returns their count.
  std::size_t move_control_point(std::size_t k, const Vec3& p);

  // The samples move_control_point(k, ...) updates: every sample (`all`: a dense column, or
  // Compact storage, which evaluates again), or the listed ones (the support of phi_k). Builds k's
  // column if it is missing; the span is valid until the next move or evaluation.
  struct Support {
    bool all = true;
    std::span<const uint32_t> samples;
  };
  Support influence_support(std::size_t k);

  // Moves several control points at once (a network edit moves a face's vertex, handles and
  // derived ribbon points together): every point's weight is added, then each touched sample's
  // geometry is recomputed once. Falls back to a full re-evaluation when the points are more than
  // the columns this evaluator keeps (building columns that evict each other every frame costs
  // more than evaluating), and when several columns are missing for points that did not move in
  // the previous call too (a one-off edit, not a drag). Returns the number of samples updated.
  struct PointMove {
    std::size_t k;
    Vec3 p;
  };
  std::size_t move_control_points(std::span<const PointMove> moves);

  // Memory held by cached influence columns, in bytes.
  std::size_t influence_bytes() const;

  // How many influence columns are kept (most recently used first out when full): at least
  // kMaxColumns, more while they fit in kColumnBudget bytes (a small face keeps the columns of
  // every point a vertex drag moves; a million-sample surface keeps kMaxColumns).
  static constexpr std::size_t kMaxColumns = 4;
  static constexpr std::size_t kColumnBudget = std::size_t(64) << 20;
  std::size_t max_columns() const;
  void set_column_budget(std::size_t bytes) { column_budget_ = bytes; }  // tests, tuning

  // Samples per parallel task of each loop (core/base/parallel_for.hpp). Small enough that a
  // thread the kernel deschedules holds little work while the others finish the rest, large
  // enough that taking a task costs little next to doing it. Chosen from `patchlab_bench
  // --grains` (2 cores shared with other work, quiet and with one core busy): drag updates of
  // 1e5 samples kept their quiet time with one core busy for grains of 128 to 1024 and lost
  // 2-3x at 64 (task overhead) and on one thread; evaluation showed no difference from 256 to
  // 8192; column builds were steadiest at 8192. A loop over at most `grain` samples runs on the
  // calling thread.
  struct Grains {
    std::size_t evaluate = 512;  // evaluate_all: one evaluate_many call per task (~0.1-0.2 ms)
    std::size_t column = 8192;   // an influence column's build
    std::size_t update = 512;    // a drag update: axpy and geometry (~10-20 us a task)
  };
  const Grains& grains() const { return grains_; }
  void set_grains(const Grains& g) { grains_ = g; }  // tests, tuning

 private:
  // Jets allocated but not initialised: the column build writes every one in parallel, and
  // zero-filling a million-sample column first would cost a third of the build.
  struct FreeJets {
    void operator()(Jet* p) const { ::operator delete[](p); }
  };
  using JetArray = std::unique_ptr<Jet[], FreeJets>;
  static JetArray allocate_jets(std::size_t count) {
    return JetArray(static_cast<Jet*>(::operator new[](count * sizeof(Jet))));
  }
  struct Column {
    std::size_t k = 0;
    uint64_t last_use = 0;
    bool dense = true;            // phi covers every sample; otherwise only `index`
    std::vector<uint32_t> index;  // sample indices with non-zero phi (sparse columns)
    JetArray phi;
    std::size_t count = 0;  // entries of phi
  };
  const Column& column(std::size_t k);
  // Keeps a dropped column's storage for the next build if it has one entry per sample: a fresh
  // million-sample column took 40 ms instead of 25, mostly page faults. Held until that build.
  void keep_storage(Column& c);
  // A patch whose domain follows its points (a side-based ribbons patch with its default
  // domain, built from its curves) is not linear in them: after its points moved it gets the
  // tessellation of its domain now (the same density) and is evaluated afresh. Returns the
  // samples updated.
  std::size_t reevaluate_moved(std::span<const PointMove> moves);
  // Geometry of samples first..first+count-1, or of index[first..first+count) if index is given.
  void update_geometry(std::span<const uint32_t> index, std::size_t first, std::size_t count);
  // Compact storage: samples first..first+count-1 from their jets, which are not kept.
  void store_compact(std::span<const SurfaceJet> jets, std::size_t first);
  // Normal and curvatures of singular sample i (Su x Sv = 0) from their limit: along its domain
  // side for a boundary sample, else towards the domain's interior.
  SurfaceGeometry singular_limit(std::size_t i) const;

  std::shared_ptr<Patch> patch_;
  bool domain_follows_points_ = false;
  std::string domain_key_;  // of the domain tessellated, when it follows the points
  std::shared_ptr<const Tessellation> tessellation_;
  SampleStorage storage_;
  std::shared_ptr<SampleBufferPool> pool_;  // where the arrays below go back to, or null
  std::vector<SurfaceJet> jets_;            // Jets storage
  std::vector<Vec3> positions_;             // Compact storage
  std::vector<uint32_t> nonfinite_;         // Compact storage: samples with a non-finite jet
  std::vector<SurfaceGeometry> geometry_;
  std::vector<Column> columns_;
  JetArray spare_;  // sample_count() entries, or empty
  uint64_t use_clock_ = 0;
  uint64_t revision_ = 0;
  std::size_t column_budget_ = kColumnBudget;
  Grains grains_;
  std::vector<std::size_t> last_batch_;  // the points move_control_points moved last time
};

}  // namespace pl
