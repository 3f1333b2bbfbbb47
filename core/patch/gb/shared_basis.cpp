#include "core/patch/gb/shared_basis.hpp"

#include <bit>
#include <cstring>
#include <list>
#include <mutex>
#include <unordered_map>
#include <unordered_set>
#include <utility>

namespace pl {

namespace {

// splitmix64's finaliser: every input bit reaches every output bit.
uint64_t mix(uint64_t x) {
  x ^= x >> 30;
  x *= 0xbf58476d1ce4e5b9ull;
  x ^= x >> 27;
  x *= 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

// The index of a block: its layout, the number of points and a hash of their bits. A block found
// under it is used only if its layout and points are the same bits (a hash collision then costs a
// basis evaluation, never a wrong surface).
std::string block_key(const std::string& layout, std::span<const Vec2> xs) {
  uint64_t h = mix(xs.size());
  for (const Vec2& x : xs)
    for (double c : {x.x, x.y}) h = mix(h ^ std::bit_cast<uint64_t>(c));
  std::string key = layout;
  key += '|';
  key += std::to_string(xs.size());
  key += '|';
  key += std::to_string(h);
  return key;
}

bool same_points(const std::vector<Vec2>& a, std::span<const Vec2> b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(Vec2)) == 0;
}

class Blocks {
 public:
  // The kept block for `key` if it holds these points; else notes the key and says whether the
  // caller should build the block (asked for before) or not (first time, or too large).
  std::shared_ptr<const std::vector<Jet>> find_or_note(const std::string& key,
                                                       std::span<const Vec2> xs, std::size_t bytes,
                                                       bool& build) {
    std::lock_guard lock(mutex_);
    build = false;
    if (const auto it = index_.find(key); it != index_.end()) {
      if (!same_points(it->second->points, xs)) return nullptr;  // a collision: not this block
      lru_.splice(lru_.begin(), lru_, it->second);               // most recently used first
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

  std::shared_ptr<const std::vector<Jet>> keep(const std::string& key, std::span<const Vec2> xs,
                                               std::shared_ptr<const std::vector<Jet>> block) {
    std::lock_guard lock(mutex_);
    if (const auto it = index_.find(key); it != index_.end()) return block;  // kept meanwhile
    const std::size_t bytes = bytes_of(block->size(), xs.size());
    while (!lru_.empty() && used_ + bytes > kSharedBasisBudget) {
      used_ -= bytes_of(lru_.back().block->size(), lru_.back().points.size());
      index_.erase(lru_.back().key);
      lru_.pop_back();
    }
    lru_.push_front({key, std::vector<Vec2>(xs.begin(), xs.end()), block});
    index_[key] = lru_.begin();
    used_ += bytes;
    return block;
  }

 private:
  static std::size_t bytes_of(std::size_t jets, std::size_t points) {
    return jets * sizeof(Jet) + points * sizeof(Vec2);
  }
  struct Entry {
    std::string key;
    std::vector<Vec2> points;
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

thread_local bool bypassed = false;

}  // namespace

SharedBasisBypass::SharedBasisBypass() : was_(std::exchange(bypassed, true)) {}
SharedBasisBypass::~SharedBasisBypass() {
  bypassed = was_;
}

bool shared_basis_bypassed() {
  return bypassed;
}

SharedBasisUse shared_basis_use() {
  return blocks().use();
}

std::shared_ptr<const std::vector<Jet>> shared_basis_block(
    const std::string& layout, std::span<const Vec2> xs, std::size_t width,
    const std::function<void(Vec2, std::span<Jet>)>& build) {
  if (bypassed) return nullptr;
  const std::string key = block_key(layout, xs);
  bool make = false;
  if (auto found = blocks().find_or_note(key, xs, xs.size() * width * sizeof(Jet), make))
    return found;
  if (!make) return nullptr;
  auto block = std::make_shared<std::vector<Jet>>(xs.size() * width);
  for (std::size_t i = 0; i < xs.size(); ++i)
    build(xs[i], std::span(*block).subspan(i * width, width));
  return blocks().keep(key, xs, std::move(block));
}

}  // namespace pl
