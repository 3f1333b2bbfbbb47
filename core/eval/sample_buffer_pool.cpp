#include "core/eval/sample_buffer_pool.hpp"

#include <algorithm>

namespace pl {

SampleBuffers SampleBuffers::fresh(std::size_t n, SampleStorage storage) {
  SampleBuffers b;
  if (storage == SampleStorage::Jets)
    b.jets.resize(n);
  else
    b.positions.resize(n);
  b.geometry.resize(n);
  return b;
}

SampleBuffers SampleBufferPool::take(std::size_t n, SampleStorage storage) {
  {
    const std::lock_guard lock(mutex_);
    const auto match = std::find_if(kept_.begin(), kept_.end(), [&](const Kept& k) {
      return k.buffers.samples() == n && k.buffers.storage() == storage;
    });
    if (match != kept_.end()) {
      SampleBuffers b = std::move(match->buffers);
      bytes_ -= b.bytes();
      kept_.erase(match);
      return b;
    }
  }
  return SampleBuffers::fresh(n, storage);
}

void SampleBufferPool::give(SampleBuffers&& b) {
  const std::size_t bytes = b.bytes();
  if (b.samples() < kMinSamples || bytes > budget_) return;  // b frees its storage
  std::vector<Kept> dropped;  // freed outside the lock: unmapping large arrays takes a while
  {
    const std::lock_guard lock(mutex_);
    while (bytes_ + bytes > budget_) {
      const auto oldest =
          std::min_element(kept_.begin(), kept_.end(),
                           [](const Kept& x, const Kept& y) { return x.given < y.given; });
      bytes_ -= oldest->buffers.bytes();
      dropped.push_back(std::move(*oldest));
      kept_.erase(oldest);
    }
    kept_.push_back({std::move(b), ++clock_});
    bytes_ += bytes;
  }
}

std::size_t SampleBufferPool::kept_bytes() const {
  const std::lock_guard lock(mutex_);
  return bytes_;
}

std::size_t SampleBufferPool::kept_count() const {
  const std::lock_guard lock(mutex_);
  return kept_.size();
}

}  // namespace pl
