#include "core/eval/patch_evaluator.hpp"

#include <algorithm>
#include <atomic>
#include <cassert>
#include <cmath>
#include <mutex>
#include <optional>

#include "core/base/parallel_for.hpp"
#include "core/patch/gb/shared_basis.hpp"
#include "core/patch/patch_types.hpp"

namespace pl {

namespace {
// A singular sample takes its normal and curvatures from their limit, extrapolated from two
// points this far and twice as far from it (Richardson: error O(h^2), rounding O(1e-16 / h)).
constexpr double kSingularStep = 1e-5;

// Samples per evaluate_many call of evaluate_all: enough to amortise the call, few enough that the
// jets are still in cache when their geometry is computed.
constexpr std::size_t kChunk = 512;

// Samples per axpy-then-geometry step of a drag update: their jets are still in L1 when the
// geometry reads them back.
constexpr std::size_t kUpdateStep = 64;

inline void axpy(SurfaceJet& s, const Vec3& d, const Jet& w) {
  s.p += w.f * d;
  s.su += w.fu * d;
  s.sv += w.fv * d;
  s.suu += w.fuu * d;
  s.suv += w.fuv * d;
  s.svv += w.fvv * d;
}
}  // namespace

PatchEvaluator::PatchEvaluator(std::shared_ptr<Patch> patch,
                               std::shared_ptr<const Tessellation> tessellation,
                               SampleStorage storage, std::shared_ptr<SampleBufferPool> pool)
    : patch_(std::move(patch)),
      tessellation_(std::move(tessellation)),
      storage_(storage),
      pool_(std::move(pool)) {
  assert(patch_ && tessellation_);
  const auto* ribbons = patch_as<RibbonPatch>(patch_.get());
  domain_follows_points_ = ribbons && ribbons->domain_follows_curves();
  if (domain_follows_points_) domain_key_ = patch_->domain().key();
  const std::size_t n = tessellation_->points.size();
  SampleBuffers b = pool_ ? pool_->take(n, storage_) : SampleBuffers::fresh(n, storage_);
  jets_ = std::move(b.jets);
  positions_ = std::move(b.positions);
  geometry_ = std::move(b.geometry);
  evaluate_all();  // overwrites every sample: kept buffers hold another evaluator's values
}

PatchEvaluator::~PatchEvaluator() {
  if (pool_) pool_->give({std::move(jets_), std::move(positions_), std::move(geometry_)});
}

namespace {
bool jet_finite(const SurfaceJet& j) {
  return finite(j.p) && finite(j.su) && finite(j.sv) && finite(j.suu) && finite(j.suv) &&
         finite(j.svv);
}
}  // namespace

bool PatchEvaluator::finite(std::size_t i) const {
  const SurfaceGeometry& g = geometry_[i];
  const bool geometry = pl::finite(g.normal) && std::isfinite(g.gaussian) &&
                        std::isfinite(g.mean) && std::isfinite(g.kmin) && std::isfinite(g.kmax);
  if (!jets_.empty()) return geometry && jet_finite(jets_[i]);
  return geometry && !std::binary_search(nonfinite_.begin(), nonfinite_.end(), uint32_t(i));
}

void PatchEvaluator::store_compact(std::span<const SurfaceJet> jets, std::size_t first) {
  const std::size_t count = jets.size();
  differential_geometry_many(jets, std::span(geometry_).subspan(first, count));
  for (std::size_t j = 0; j < count; ++j) {
    const std::size_t i = first + j;
    positions_[i] = jets[j].p;
    if (geometry_[i].status == GeometryStatus::Singular) geometry_[i] = singular_limit(i);
    if (!jet_finite(jets[j])) {  // rare: a lock is cheaper than per-task lists
      static std::mutex nonfinite_mutex;
      const std::lock_guard lock(nonfinite_mutex);
      nonfinite_.push_back(static_cast<uint32_t>(i));
    }
  }
}

void PatchEvaluator::update_geometry(std::span<const uint32_t> index, std::size_t first,
                                     std::size_t count) {
  // Batched over the samples, then the rare singular ones again from the limit inside.
  if (index.empty())
    differential_geometry_many(std::span(jets_).subspan(first, count),
                               std::span(geometry_).subspan(first, count));
  else
    differential_geometry_many(jets_, index.subspan(first, count), geometry_);
  for (std::size_t j = first; j < first + count; ++j) {
    const std::size_t i = index.empty() ? j : index[j];
    if (geometry_[i].status == GeometryStatus::Singular) geometry_[i] = singular_limit(i);
  }
}

SurfaceGeometry PatchEvaluator::singular_limit(std::size_t i) const {
  const Domain& domain = patch_->domain();
  // The limit at x from the points `at(h)`, `at(2h)`; nothing if those are singular too.
  const auto limit = [&](const auto& at) -> std::optional<SurfaceGeometry> {
    const SurfaceGeometry a = differential_geometry(patch_->evaluate(at(kSingularStep)));
    const SurfaceGeometry b = differential_geometry(patch_->evaluate(at(2 * kSingularStep)));
    if (a.status == GeometryStatus::Singular || b.status == GeometryStatus::Singular)
      return std::nullopt;
    SurfaceGeometry g;
    g.normal = glm::normalize(2.0 * a.normal - b.normal);
    g.gaussian = 2 * a.gaussian - b.gaussian;
    g.mean = 2 * a.mean - b.mean;
    g.kmin = 2 * a.kmin - b.kmin;
    g.kmax = 2 * a.kmax - b.kmax;
    g.status = GeometryStatus::Singular;
    return g;
  };
  // On the boundary, along the side: a corner where two sides run on in one direction (a split
  // edge's vertex) is singular only at that point, and the faces sharing the edge agree on the
  // limit along it. Elsewhere (or if the side is degenerate itself), towards the interior.
  const Tessellation& t = *tessellation_;
  for (std::size_t s = 0; s < t.sides.size(); ++s) {
    const auto& side = t.sides[s];
    const auto at = std::find(side.begin(), side.end(), static_cast<uint32_t>(i));
    if (at == side.end()) continue;
    const double u = double(at - side.begin()) / t.density, dir = u < 0.5 ? 1 : -1;
    if (auto g = limit([&](double h) { return domain.side_point(int(s), u + dir * h); })) return *g;
    break;
  }
  const Vec2 x = t.points[i], d = domain.interior_point() - x;
  if (auto g = limit([&](double h) { return x + h * d; })) return *g;
  SurfaceGeometry g = differential_geometry(patch_->evaluate(x + 1e-3 * d));
  g.status = GeometryStatus::Singular;
  return g;
}

void PatchEvaluator::evaluate_all() {
  const auto& xs = tessellation_->points;
  nonfinite_.clear();
  // Chunks through evaluate_many, so patch types with a batched (SIMD) form use it. A caller that
  // evaluates a patch on its own (SharedBasisBypass) means it for every chunk, on any thread.
  const bool alone = shared_basis_bypassed();
  parallel_chunks(xs.size(), grains_.evaluate, [&](std::size_t first, std::size_t last) {
    std::optional<SharedBasisBypass> own;
    if (alone) own.emplace();
    for (std::size_t b = first; b < last; b += kChunk) {
      const std::size_t e = std::min(last, b + kChunk);
      if (storage_ == SampleStorage::Jets) {
        patch_->evaluate_many(std::span(xs).subspan(b, e - b), std::span(jets_).subspan(b, e - b));
        update_geometry({}, b, e - b);
      } else {  // the chunk's jets live only until its geometry is computed
        SurfaceJet chunk[kChunk];
        const std::span<SurfaceJet> jets(chunk, e - b);
        patch_->evaluate_many(std::span(xs).subspan(b, e - b), jets);
        store_compact(jets, b);
      }
    }
  });
  std::sort(nonfinite_.begin(), nonfinite_.end());
  // Columns depend only on the basis, but a full rebuild starts clean.
  for (Column& c : columns_) keep_storage(c);
  columns_.clear();
  ++revision_;
}

void PatchEvaluator::keep_storage(Column& c) {
  if (c.dense && c.count == jets_.size()) spare_ = std::move(c.phi);
}

const PatchEvaluator::Column& PatchEvaluator::column(std::size_t k) {
  ++use_clock_;
  for (Column& c : columns_)
    if (c.k == k) {
      c.last_use = use_clock_;
      return c;
    }
  if (columns_.size() >= max_columns()) {  // the least recently used one goes
    auto oldest =
        std::min_element(columns_.begin(), columns_.end(),
                         [](const Column& a, const Column& b) { return a.last_use < b.last_use; });
    keep_storage(*oldest);
    columns_.erase(oldest);
  }
  Column c;
  c.k = k;
  c.last_use = use_clock_;
  const auto& xs = tessellation_->points;
  c.count = xs.size();
  c.phi = spare_ ? std::move(spare_) : allocate_jets(c.count);
  // Evaluate in parallel chunks: influence() is const and thread-safe.
  std::atomic<std::size_t> nonzero_count = 0;
  parallel_chunks(xs.size(), grains_.column, [&](std::size_t b, std::size_t e) {
    patch_->influence(k, std::span(xs).subspan(b, e - b), std::span(&c.phi[b], e - b));
    std::size_t here = 0;
    for (std::size_t i = b; i < e; ++i) here += !c.phi[i].is_zero();
    nonzero_count += here;
  });
  const std::size_t nonzero = nonzero_count;
  if (nonzero * 2 < c.count) {  // sparse: keep only the samples it moves
    c.dense = false;
    JetArray packed = allocate_jets(nonzero);
    c.index.reserve(nonzero);
    for (std::size_t i = 0; i < c.count; ++i)
      if (!c.phi[i].is_zero()) {
        packed[c.index.size()] = c.phi[i];
        c.index.push_back(static_cast<uint32_t>(i));
      }
    c.phi = std::move(packed);
    c.count = nonzero;
  }
  columns_.push_back(std::move(c));
  return columns_.back();
}

void PatchEvaluator::prepare_influence(std::size_t k) {
  if (storage_ == SampleStorage::Jets) column(k);  // compact samples are evaluated again
}

std::size_t PatchEvaluator::reevaluate_moved(std::span<const PointMove> moves) {
  for (const PointMove& m : moves) patch_->set_control_point(m.k, m.p);
  const Domain& domain = patch_->domain();
  if (std::string key = domain.key(); key != domain_key_) {
    domain_key_ = std::move(key);
    tessellation_ = std::make_shared<const Tessellation>(domain.tessellate(tessellation_->density));
    const std::size_t n = tessellation_->points.size();
    SampleBuffers b = SampleBuffers::fresh(n, storage_);
    jets_ = std::move(b.jets);
    positions_ = std::move(b.positions);
    geometry_ = std::move(b.geometry);
  }
  evaluate_all();
  return sample_count();
}

std::size_t PatchEvaluator::move_control_point(std::size_t k, const Vec3& p) {
  assert(k < patch_->size());
  if (domain_follows_points_) {
    const PointMove move{k, p};
    return reevaluate_moved(std::span(&move, 1));
  }
  if (storage_ == SampleStorage::Compact) {
    patch_->set_control_point(k, p);
    evaluate_all();
    return sample_count();
  }
  const Vec3 d = p - patch_->control_point(k);
  patch_->set_control_point(k, p);
  const Column& c = column(k);
  const std::size_t n = c.count;
  // Dense columns update every sample (a zero weight adds zeros and recomputes the same geometry):
  // cheaper than testing each weight.
  const auto index = c.dense ? std::span<const uint32_t>() : std::span<const uint32_t>(c.index);
  parallel_chunks(n, grains_.update, [&](std::size_t first, std::size_t last) {
    for (std::size_t b = first; b < last; b += kUpdateStep) {
      const std::size_t e = std::min(last, b + kUpdateStep);
      if (index.empty())
        for (std::size_t i = b; i < e; ++i) axpy(jets_[i], d, c.phi[i]);
      else
        for (std::size_t i = b; i < e; ++i) axpy(jets_[index[i]], d, c.phi[i]);
      update_geometry(index, b, e - b);
    }
  });
  // A point without influence here (an empty sparse column: e.g. a Catmull–Clark vertex far from
  // this face) changed no sample, so the renderer has nothing to re-upload.
  if (n > 0) ++revision_;
  return static_cast<std::size_t>(n);
}

PatchEvaluator::Support PatchEvaluator::influence_support(std::size_t k) {
  if (storage_ == SampleStorage::Compact) return {};
  const Column& c = column(k);
  if (c.dense) return {};
  return {false, std::span<const uint32_t>(c.index)};
}

std::size_t PatchEvaluator::max_columns() const {
  const std::size_t column_bytes = std::max<std::size_t>(1, jets_.size() * sizeof(Jet));
  return std::max(kMaxColumns, column_budget_ / column_bytes);
}

std::size_t PatchEvaluator::move_control_points(std::span<const PointMove> moves) {
  if (moves.size() == 1) return move_control_point(moves[0].k, moves[0].p);
  if (moves.empty()) return 0;
  if (domain_follows_points_) return reevaluate_moved(moves);
  if (storage_ == SampleStorage::Compact) {  // one evaluation for all of them
    for (const PointMove& m : moves) patch_->set_control_point(m.k, m.p);
    evaluate_all();
    return sample_count();
  }
  if (moves.size() > max_columns()) {
    for (const PointMove& m : moves) patch_->set_control_point(m.k, m.p);
    evaluate_all();
    return jets_.size();
  }
  // Columns pay off only when the same points move again (a drag): a one-off edit of several
  // points whose columns are missing (the fine view's sync when a drag ends) is cheaper as one
  // full evaluation than as several column builds, each about as costly for most patch types.
  std::vector<std::size_t> keys;
  std::size_t missing = 0;
  for (const PointMove& m : moves) {
    keys.push_back(m.k);
    missing +=
        std::none_of(columns_.begin(), columns_.end(), [&](const Column& c) { return c.k == m.k; });
  }
  const bool repeated = keys == last_batch_;
  last_batch_ = std::move(keys);
  if (missing > 1 && !repeated) {
    for (const PointMove& m : moves) patch_->set_control_point(m.k, m.p);
    evaluate_all();
    return jets_.size();
  }
  // Build (or touch) every column first: the batch is the most recently used, so none of its
  // columns is evicted by another's build, and the pointers taken afterwards stay valid.
  for (const PointMove& m : moves) column(m.k);
  std::vector<const Column*> cols;
  std::vector<Vec3> deltas;
  bool all_dense = true;
  for (const PointMove& m : moves) {
    const Column* c = &*std::find_if(columns_.begin(), columns_.end(),
                                     [&](const Column& col) { return col.k == m.k; });
    all_dense = all_dense && c->dense;
    cols.push_back(c);
    deltas.push_back(m.p - patch_->control_point(m.k));
  }
  if (!all_dense) {  // sparse supports differ: one point at a time touches only its samples
    std::size_t touched = 0;
    for (const PointMove& m : moves) touched = std::max(touched, move_control_point(m.k, m.p));
    return touched;
  }
  for (const PointMove& m : moves) patch_->set_control_point(m.k, m.p);
  // Each sample adds the points' weights in the order of `moves`, whatever thread runs it.
  parallel_chunks(jets_.size(), grains_.update, [&](std::size_t first, std::size_t last) {
    for (std::size_t b = first; b < last; b += kUpdateStep) {
      const std::size_t e = std::min(last, b + kUpdateStep);
      for (std::size_t m = 0; m < cols.size(); ++m)
        for (std::size_t i = b; i < e; ++i) axpy(jets_[i], deltas[m], cols[m]->phi[i]);
      update_geometry({}, b, e - b);
    }
  });
  ++revision_;
  return jets_.size();
}

std::size_t PatchEvaluator::influence_bytes() const {
  std::size_t b = 0;
  for (const Column& c : columns_) b += c.count * sizeof(Jet) + c.index.capacity() * 4;
  if (spare_) b += jets_.size() * sizeof(Jet);
  return b;
}

}  // namespace pl
