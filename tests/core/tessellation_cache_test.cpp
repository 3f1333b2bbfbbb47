// The tessellation cache shares one tessellation per domain and density, and does not grow for
// ever when domains keep changing (a side-based face's polygon follows its curves: a new domain
// every drag frame): past its bound it drops what no one else holds, and keeps what is in use.
#include "core/domain/tessellation_cache.hpp"

#include <gtest/gtest.h>

#include "core/domain/convex_polygon.hpp"

namespace pl {
namespace {

ConvexPolygonDomain triangle(int i) {
  return ConvexPolygonDomain({{0, 0}, {1 + 1e-3 * i, 0}, {0, 1}});
}

TEST(TessellationCache, SharesAndStaysBoundedWhenDomainsKeepChanging) {
  TessellationCache cache;
  const auto a = cache.get(triangle(0), 4), b = cache.get(triangle(0), 4);
  EXPECT_EQ(a, b);                          // shared
  EXPECT_NE(a, cache.get(triangle(0), 5));  // another density, another tessellation
  const auto held = cache.get(triangle(1), 4);
  for (int i = 2; i < 3 * int(TessellationCache::kPruneAt); ++i) cache.get(triangle(i), 4);
  EXPECT_LE(cache.size(), TessellationCache::kPruneAt);
  // What is held stays shared: asking again gives the same tessellation.
  EXPECT_EQ(cache.get(triangle(1), 4), held);
  EXPECT_EQ(cache.get(triangle(0), 4), a);
}

}  // namespace
}  // namespace pl
