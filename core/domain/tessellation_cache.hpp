// Shares tessellations between patches: one per (domain key, density). Thread-safe. Once it holds
// kPruneAt tessellations (then twice what it kept), those no one else holds are dropped.
#pragma once

#include <map>
#include <memory>
#include <mutex>
#include <string>

#include "core/domain/domain.hpp"

namespace pl {

class TessellationCache {
 public:
  std::shared_ptr<const Tessellation> get(const Domain& domain, int density);
  std::size_t size() {
    std::lock_guard lock(mutex_);
    return cache_.size();
  }
  static constexpr std::size_t kPruneAt = 4096;

 private:
  std::mutex mutex_;
  std::map<std::pair<std::string, int>, std::shared_ptr<const Tessellation>> cache_;
  std::size_t prune_at_ = kPruneAt;
};

}  // namespace pl
