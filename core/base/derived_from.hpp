// Derived data kept current by request: a value computed from inputs that a key names (a
// revision, a serial, a tuple of them). require(key) says whether the value must be computed
// again: true the first time and whenever the key differs from the one it was last computed for.
// It replaces counters kept by hand next to each derived value ("uploaded_serial_ = UINT64_MAX"):
//   if (copy_state.require(live.revision())) copy.update(live.draw());
// invalidate() forces the next require() to say so (the inputs changed in a way no key names).
#pragma once

#include <optional>
#include <utility>

namespace pl {

template <class Key>
class DerivedFrom {
 public:
  // True when the value is stale for `key` (it is then taken to be computed for it).
  bool require(const Key& key) {
    if (key_ && *key_ == key) return false;
    key_ = key;
    return true;
  }
  bool current(const Key& key) const { return key_ && *key_ == key; }
  void invalidate() { key_.reset(); }

 private:
  std::optional<Key> key_;
};

}  // namespace pl
