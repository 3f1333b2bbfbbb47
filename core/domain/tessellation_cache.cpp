#include "core/domain/tessellation_cache.hpp"

#include <algorithm>

namespace pl {

std::shared_ptr<const Tessellation> TessellationCache::get(const Domain& domain, int density) {
  std::lock_guard lock(mutex_);
  // Domains that follow their patches (a side-based face's polygon is built from its curves: a
  // new one every drag frame) would grow the cache for a whole session: past a bound, the
  // tessellations no evaluator holds any more are dropped (those in use stay shared), and the next
  // bound is twice what stays, so a scene of many domains in use is not scanned at every call.
  if (cache_.size() >= prune_at_) {
    std::erase_if(cache_, [](const auto& entry) { return entry.second.use_count() == 1; });
    prune_at_ = std::max(kPruneAt, 2 * cache_.size());
  }
  auto& slot = cache_[{domain.key(), density}];
  if (!slot) slot = std::make_shared<const Tessellation>(domain.tessellate(density));
  return slot;
}

}  // namespace pl
