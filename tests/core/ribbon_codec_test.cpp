// The `ribbons` patch type in scene files: written and read back it is the same patch (every
// setting and curve form kept, the same surface bit for bit), and a network face's ribbon scheme
// survives a save.
#include <gtest/gtest.h>

#include "core/base/data_error.hpp"
#include "core/io/scene_io.hpp"
#include "core/scene/network_edit.hpp"
#include "ribbon_test_util.hpp"

namespace pl {
namespace {

using transfinite::RibbonScheme;

TEST(RibbonCodec, WriteAndReadGiveTheSamePatch) {
  auto sides = test::reference_face(5);
  sides[1].curve = curve_knot_inserted(sides[1].curve, 0.4);  // a bspline side
  RibbonPatchOptions o;
  o.midpoint = Vec3(0.3, 0.2, 2.5);
  o.twists = transfinite::TwistEstimate::ForwardDifference;
  o.domain = std::vector<Vec2>{{1, 0}, {0.3, 0.9}, {-0.8, 0.6}, {-0.8, -0.6}, {0.3, -0.95}};
  Scene scene;
  scene.patches.push_back({"mp", std::make_shared<RibbonPatch>(RibbonScheme::Midpoint, sides, o)});
  scene.patches.push_back(
      {"cb", std::make_shared<RibbonPatch>(RibbonScheme::CornerBased, test::reference_face(3))});
  const std::string text = scene_to_json(scene);
  EXPECT_NE(text.find("\"ribbons\""), std::string::npos);
  const Scene back = parse_scene(text, "round trip");
  ASSERT_EQ(back.patches.size(), 2u);
  EXPECT_EQ(scene_to_json(back), text);
  for (std::size_t k = 0; k < 2; ++k) {
    const auto& a = dynamic_cast<const RibbonPatch&>(*scene.patches[k].patch);
    const auto& b = dynamic_cast<const RibbonPatch&>(*back.patches[k].patch);
    EXPECT_EQ(a.scheme(), b.scheme());
    EXPECT_EQ(a.control_points(), b.control_points());
    for (Vec2 x : a.domain().tessellate(6).points) EXPECT_EQ(a.evaluate(x).p, b.evaluate(x).p);
  }
  const auto& mp = dynamic_cast<const RibbonPatch&>(*back.patches[0].patch);
  EXPECT_EQ(mp.sides()[1].curve.type, CurveType::BSpline);
  EXPECT_EQ(mp.options().twists, transfinite::TwistEstimate::ForwardDifference);
  EXPECT_FALSE(mp.default_domain());
}

TEST(RibbonCodec, NetworkFaceSchemesSurviveASave) {
  Scene scene = parse_scene(R"({"patchlab": 1, "network": {
    "vertices": [[0,0,0],[1,0,0],[1,1,0],[0,1,0]],
    "edges": [{"v":[0,1],"handles":[[0.3,0,0],[0.6,0,0]]},{"v":[1,2],"handles":[[1,0.3,0],[1,0.6,0]]},
              {"v":[2,3],"handles":[[0.6,1,0],[0.3,1,0]]},{"v":[3,0],"handles":[[0,0.6,0],[0,0.3,0]]}],
    "faces": [{"loop":[0,1,2,3], "scheme": "composite-ribbon"}]}})",
                            "test");
  EXPECT_EQ(scene.network->faces[0].scheme, FaceScheme::CompositeRibbon);
  for (FaceScheme s : all_face_schemes()) {
    scene.network->faces[0].scheme = s;
    const Scene back = parse_scene(scene_to_json(scene), "round trip");
    EXPECT_EQ(back.network->faces[0].scheme, s) << scheme_keyword(s);
    EXPECT_EQ(parse_scheme_keyword(scheme_keyword(s)), s);
  }
  scene.network->faces[0].scheme = FaceScheme::MidpointCoons;
  scene.network->faces[0].fullness = 1.5;
  const std::string text = scene_to_json(scene);
  EXPECT_EQ(parse_scene(text, "round trip").network->faces[0].fullness, 1.5);
  // Only the midpoint schemes have a fullness.
  std::string other = text;
  other.replace(other.find("midpoint-coons"), 14, "gb");
  EXPECT_THROW(parse_scene(other, "other"), DataError);
}

}  // namespace
}  // namespace pl
