#include "core/base/derived_from.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <tuple>

namespace pl {
namespace {

TEST(DerivedFrom, StaleFirstThenOnlyWhenTheKeyChanges) {
  DerivedFrom<uint64_t> d;
  EXPECT_FALSE(d.current(7));
  EXPECT_TRUE(d.require(7));
  EXPECT_TRUE(d.current(7));
  EXPECT_FALSE(d.require(7));
  EXPECT_TRUE(d.require(8));
  EXPECT_TRUE(d.require(7)) << "a key seen before but not last is stale again";
  d.invalidate();
  EXPECT_FALSE(d.current(7));
  EXPECT_TRUE(d.require(7));
}

TEST(DerivedFrom, TupleKeysCompareEveryPart) {
  DerivedFrom<std::tuple<uint64_t, uint64_t>> d;
  EXPECT_TRUE(d.require({1, 2}));
  EXPECT_FALSE(d.require({1, 2}));
  EXPECT_TRUE(d.require({1, 3}));
  EXPECT_TRUE(d.require({2, 3}));
}

}  // namespace
}  // namespace pl
