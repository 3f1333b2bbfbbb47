// Every patch type that can appear in a scene must round-trip through its codec: a type missing
// from core/io/patch_codecs.cpp would make saving a scene fail.
#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <sstream>

#include "core/io/patch_codec.hpp"
#include "core/io/scene_io.hpp"

namespace pl {
namespace {

TEST(PatchCodecs, RegistryHoldsEveryDocumentedTypeOnce) {
  std::set<std::string> seen;
  for (const PatchCodec& c : patch_codecs()) EXPECT_TRUE(seen.insert(c.type).second) << c.type;
  for (const char* type :
       {"bezier", "gb", "gregory-quad", "gregory-tri", "gb-ribbons", "interpolating", "hermite",
        "bspline", "nurbs", "coons-network", "pair-join", "gap-fill", "catmull-clark"})
    EXPECT_TRUE(seen.count(type)) << "no codec for " << type;
}

}  // namespace
}  // namespace pl
