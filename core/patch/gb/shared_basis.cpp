#include "core/patch/gb/shared_basis.hpp"

#include <bit>
#include <list>
#include <mutex>
#include <unordered_map>
#include <unordered_set>

namespace pl {

namespace {

// The key of a block: its layout, the number of points and a 64-bit hash of their bits, with the
// first and last points spelled out.
std::string block_key(const std::string& layout, std::span<const Vec2> xs) {
  uint64_t h = 1469598103934665603ull;
  for (const Vec2& x : xs)
    for (double c : {x.x, x.y}) {
      h ^= std::bit_cast<uint64_t>(c);
      h *= 1099511628211ull;
    }
  std::string key = layout;
  const auto add = [&key](uint64_t v) {
    key += '|';
    key += std::to_string(v);
  };
  add(xs.size());
  add(h);
  if (!xs.empty())
    for (const Vec2& x : {xs.front(), xs.back()})
      for (double c : {x.x, x.y}) add(std::bit_cast<uint64_t>(c));
  return key;
}

class Blocks {
 public:
  std::shared_ptr<const std::vector<Jet>> find_or_note(const std::string& key, std::size_t bytes,
                                                       bool& build) {
    std::lock_guard lock(mutex_);
    build = false;
    if (const auto it = index_.find(key); it != index_.end()) {
      lru_.splice(lru_.begin(), lru_, it->second);  // most recently used first
      return it->second->block;
    }
    if (bytes > kSharedBasisBudget) return nullptr;
    // The first asker evaluates on its own; only a hash of the key is remembered.
    if (seen_.insert(std::hash<std::string>{}(key)).second) {
      if (seen_.size() > 65536) seen_.clear();
      return nullptr;
    }
    build = true;
    return nullptr;
  }

  SharedBasisUse use() {
    std::lock_guard lock(mutex_);
    return {lru_.size(), used_};
  }

  std::shared_ptr<const std::vector<Jet>> keep(const std::string& key,
                                               std::shared_ptr<const std::vector<Jet>> block) {
    std::lock_guard lock(mutex_);
    if (const auto it = index_.find(key); it != index_.end()) return it->second->block;
    const std::size_t bytes = block->size() * sizeof(Jet);
    while (!lru_.empty() && used_ + bytes > kSharedBasisBudget) {
      used_ -= lru_.back().block->size() * sizeof(Jet);
      index_.erase(lru_.back().key);
      lru_.pop_back();
    }
    lru_.push_front({key, block});
    index_[key] = lru_.begin();
    used_ += bytes;
    return block;
  }

 private:
  struct Entry {
    std::string key;
    std::shared_ptr<const std::vector<Jet>> block;
  };
  std::mutex mutex_;
  std::list<Entry> lru_;
  std::unordered_map<std::string, std::list<Entry>::iterator> index_;
  std::unordered_set<std::size_t> seen_;
  std::size_t used_ = 0;
};

Blocks& blocks() {
  static Blocks b;
  return b;
}

}  // namespace

SharedBasisUse shared_basis_use() {
  return blocks().use();
}

std::shared_ptr<const std::vector<Jet>> shared_basis_block(
    const std::string& layout, std::span<const Vec2> xs, std::size_t width,
    const std::function<void(Vec2, std::span<Jet>)>& build) {
  const std::string key = block_key(layout, xs);
  bool make = false;
  if (auto found = blocks().find_or_note(key, xs.size() * width * sizeof(Jet), make)) return found;
  if (!make) return nullptr;
  auto block = std::make_shared<std::vector<Jet>>(xs.size() * width);
  for (std::size_t i = 0; i < xs.size(); ++i)
    build(xs[i], std::span(*block).subspan(i * width, width));
  return blocks().keep(key, std::move(block));
}

}  // namespace pl
