#include "core/domain/tessellation_cache.hpp"

namespace pl {

std::shared_ptr<const Tessellation> TessellationCache::get(const Domain& domain, int density) {
  std::lock_guard lock(mutex_);
  auto& slot = cache_[{domain.key(), density}];
  if (!slot) slot = std::make_shared<const Tessellation>(domain.tessellate(density));
  return slot;
}

}  // namespace pl
