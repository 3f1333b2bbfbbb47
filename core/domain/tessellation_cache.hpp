// Shares tessellations between patches: one per (domain key, density). Thread-safe.
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

 private:
  std::mutex mutex_;
  std::map<std::pair<std::string, int>, std::shared_ptr<const Tessellation>> cache_;
};

}  // namespace pl
