// .gbp reading/writing and the "gb" scene codec: lossless round trips and DataErrors with places.
#include <gtest/gtest.h>

#include <cstring>
#include <nlohmann/json.hpp>

#include "core/base/data_error.hpp"
#include "core/io/input_limits.hpp"
#include "core/io/scene_io.hpp"
#include "gb_test_util.hpp"

namespace pl {
namespace {

// Doubles with random bit patterns (finite), so every digit of the 17 matters.
GBPatch random_bits_gb(int n, int d, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::vector<Vec3> p(GBPatch::point_count(n, d));
  for (Vec3& q : p)
    for (int c = 0; c < 3; ++c) {
      double x;
      do {
        const uint64_t bits = rng();
        std::memcpy(&x, &bits, sizeof x);
      } while (!std::isfinite(x) || std::fabs(x) > kMaxCoordinate);  // every bit pattern read
      q[c] = x;
    }
  return GBPatch(n, d, std::move(p));
}

void expect_same_bits(const GBPatch& a, const GBPatch& b) {
  ASSERT_EQ(a.sides(), b.sides());
  ASSERT_EQ(a.degree(), b.degree());
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k)
    ASSERT_EQ(std::memcmp(&a.control_point(k), &b.control_point(k), sizeof(Vec3)), 0) << k;
}

TEST(GBIo, GbpRoundTripIsBitExact) {
  for (int n = 3; n <= 7; ++n)
    for (int d = 1; d <= 6; ++d) {
      const GBPatch g = random_bits_gb(n, d, 100 * n + d);
      const std::string text = gbp_to_text(g);
      const GBPatch back = parse_gbp(text, "mem.gbp");
      expect_same_bits(g, back);
      EXPECT_EQ(gbp_to_text(back), text);
    }
}

TEST(GBIo, SceneCodecRoundTripIsBitExactAndInGbpOrder) {
  const GBPatch g = random_bits_gb(5, 5, 9);
  Scene scene;
  scene.patches.push_back({"p", std::make_shared<GBPatch>(g)});
  const std::string json = scene_to_json(scene);
  const auto j = nlohmann::json::parse(json);
  EXPECT_EQ(j["patches"][0]["type"], "gb");
  EXPECT_EQ(j["patches"][0]["sides"], 5);
  EXPECT_EQ(j["patches"][0]["degree"], 5);
  const Scene back = parse_scene(json, "mem.json");
  ASSERT_EQ(back.patches.size(), 1u);
  expect_same_bits(g, dynamic_cast<const GBPatch&>(*back.patches[0].patch));
}

TEST(GBIo, SceneCodecErrorsNameThePath) {
  struct Case {
    std::string patch, where;
  } cases[] = {
      {R"({"type":"gb","sides":2,"degree":3,"points":[]})", "patches[0].sides"},
      {R"({"type":"gb","sides":5,"degree":0,"points":[]})", "patches[0].degree"},
      {R"({"type":"gb","sides":3,"degree":1,"points":[[0,0,0]]})", "patches[0].points"},
      {R"({"type":"gb","sides":3,"degree":1})", "points"},
      {R"({"type":"gb","sides":3,"degree":1,"points":[],"weights":[]})", "weights"},
  };
  for (const Case& c : cases) {
    try {
      parse_scene(R"({"patchlab":1,"patches":[)" + c.patch + "]}", "s.json");
      ADD_FAILURE() << "accepted " << c.patch;
    } catch (const DataError& e) {
      EXPECT_EQ(e.source(), "s.json");
      EXPECT_NE(std::string(e.what()).find(c.where), std::string::npos) << e.what();
    }
  }
}

TEST(GBIo, ParseErrorsCarryTheTokenNumber) {
  const auto where = [](const std::string& text) {
    try {
      parse_gbp(text, "f.gbp");
    } catch (const DataError& e) {
      EXPECT_EQ(e.source(), "f.gbp");
      return e.where();
    }
    return std::string("accepted");
  };
  EXPECT_EQ(where(""), "token 1");
  EXPECT_EQ(where("3"), "token 2");
  EXPECT_EQ(where("-3 3"), "token 1");
  EXPECT_EQ(where("3 -1"), "token 2");
  EXPECT_EQ(where("99 3"), "token 1");  // beyond the supported 16 sides
  EXPECT_EQ(where("3 1\n0 0 0\n1 0 0\n0 1 0\n1 1"), "token 14");
  EXPECT_EQ(where("3 1 0 0 0 1 0 0 0 1 0 1 1 1 1"), "token 15");
  EXPECT_EQ(where("3 1 0 0 0 1 0 0 0 1 0 1 1 -inf"), "token 14");
  EXPECT_EQ(where("3 1 0 0 0 1 0 0 0 1 0 1 1 0x10"), "token 14");
  EXPECT_EQ(where("3 1 0 0 0 1 0 0 0 1 0 1 1 1"), "accepted");
}

}  // namespace
}  // namespace pl
