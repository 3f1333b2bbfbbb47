// A fixed-size array whose elements are NOT initialised on construction. Jet and SurfaceJet
// zero themselves, and per-sample scratch arrays sized for the largest polygon would otherwise
// cost a multi-kilobyte memset on every evaluation. Elements must be assigned before use.
#pragma once

#include <type_traits>

namespace pl {

template <class T, int N>
union Scratch {
  static_assert(std::is_trivially_destructible_v<T>);
  Scratch() {}  // NOLINT: deliberately leaves v uninitialised
  T v[N];
  T& operator[](int i) { return v[i]; }
  const T& operator[](int i) const { return v[i]; }
  T* data() { return v; }
  const T* data() const { return v; }
};

}  // namespace pl
