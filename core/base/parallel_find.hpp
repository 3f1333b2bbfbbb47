// The first index that satisfies a test, searched in parallel: the same answer a loop from 0
// gives, whatever the threads do.
#pragma once

#include <atomic>
#include <cstddef>

#include "core/base/parallel_for.hpp"

namespace pl {

// The smallest i in [0, n) with bad(i), or n if there is none. parallel_chunks over tasks of
// `grain`: a task stops at its first hit and at the indices past the smallest hit found so far.
template <class Test>
std::size_t parallel_find_first(std::size_t n, std::size_t grain, Test&& bad) {
  std::atomic<std::size_t> first = n;
  parallel_chunks(n, grain, [&](std::size_t b, std::size_t e) {
    for (std::size_t i = b; i < e && i < first.load(std::memory_order_relaxed); ++i)
      if (bad(i)) {
        std::size_t seen = first.load();
        while (i < seen && !first.compare_exchange_weak(seen, i)) {
        }
        return;
      }
  });
  return first;
}

}  // namespace pl
