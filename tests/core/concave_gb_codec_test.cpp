// The gb-ribbons scene type: round trip, and DataErrors naming the patch for bad data.
#include <gtest/gtest.h>

#include "core/base/data_error.hpp"
#include "core/io/scene_io.hpp"
#include "core/patch/gb/gb_ribbon_patch.hpp"

namespace pl {
namespace {

const char* kLScene = R"({"patchlab": 1, "patches": [{"type": "gb-ribbons", "name": "L",
  "domain": [[0,0],[2,0],[2,1],[1,1],[1,2],[0,2]],
  "ribbons": [
    {"degree": 1, "layers": 2, "points": [[0,2,0],[0,0,0], [0.2,2,0.1],[0.2,0,0.1]]},
    {"degree": 2, "layers": 2, "points": [[0,0,0],[1,0,0.2],[2,0,0], [0,0.2,0],[1,0.2,0.3],[2,0.2,0]]},
    {"degree": 1, "layers": 2, "points": [[2,0,0],[2,1,0], [1.8,0,0.1],[1.8,1,0.1]]},
    {"degree": 1, "layers": 2, "points": [[2,1,0],[1,1,0], [2,0.8,0],[1,0.8,0]]},
    {"degree": 1, "layers": 3, "points": [[1,1,0],[1,2,0], [0.8,1,0],[0.8,2,0], [0.6,1,0],[0.6,2,0]]},
    {"degree": 1, "layers": 2, "points": [[1,2,0],[0,2,0], [1,1.8,0.1],[0,1.8,0.1]]}]}]})";

TEST(GBRibbonCodec, RoundTrip) {
  const Scene s = parse_scene(kLScene, "l.json");
  ASSERT_EQ(s.patches.size(), 1u);
  const auto& p = dynamic_cast<const GBRibbonPatch&>(*s.patches[0].patch);
  EXPECT_EQ(p.type(), "gb-ribbons");
  EXPECT_EQ(p.sides(), 6);
  EXPECT_EQ(p.degree(1), 2);
  EXPECT_EQ(p.layers(4), 3);
  // Shared corners are stored once: 6 boundary + sum over sides of (l-1)(d+1) inner points.
  EXPECT_EQ(p.size(), std::size_t(1 + 2 + 1 + 1 + 1 + 1) + 2 + 3 + 2 + 2 + 4 + 2);
  const Scene back = parse_scene(scene_to_json(s), "again.json");
  const auto& q = dynamic_cast<const GBRibbonPatch&>(*back.patches[0].patch);
  EXPECT_EQ(q.control_points(), p.control_points());
  EXPECT_EQ(q.polygon().vertices(), p.polygon().vertices());
  const Vec2 x(0.5, 0.7);
  EXPECT_EQ(q.evaluate(x).p, p.evaluate(x).p);
}

TEST(GBRibbonCodec, BadDataNamesThePatch) {
  std::string bad = kLScene;
  bad.replace(bad.find("[[0,2,0],[0,0,0]"), 16, "[[0,2,0],[0,0,1]");  // corner mismatch
  try {
    parse_scene(bad, "bad.json");
    FAIL() << "expected a DataError";
  } catch (const DataError& e) {
    EXPECT_EQ(e.source(), "bad.json");
    EXPECT_NE(e.where().find("patches[0]"), std::string::npos) << e.what();
  }
  std::string crossed = kLScene;
  crossed.replace(crossed.find("[2,1],[1,1]"), 11, "[2,1],[-1,1]");  // crosses side 0
  EXPECT_THROW(parse_scene(crossed, "x.json"), DataError);
}

}  // namespace
}  // namespace pl
