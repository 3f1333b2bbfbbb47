// `patchlab convert` between .gbp and .json scenes, .gbp as CLI input, and every malformed-.gbp
// case of gbp-format.md: exit 1, one message naming the file and the token.
#include <gtest/gtest.h>

#include "cli_test_util.hpp"
#include "core/io/gbp_io.hpp"
#include "core/io/scene_io.hpp"

namespace pl::test {
namespace {

std::filesystem::path reference(const std::string& name) {
  return std::filesystem::path(PATCHLAB_TEST_DATA_DIR) / "gb" / (name + ".gbp");
}

TEST(ConvertGbp, ReferenceModelsRoundTripBitExact) {
  ASSERT_TRUE(std::filesystem::exists(reference("cagd86")))
      << "GB reference folder is missing: " << reference("cagd86").parent_path();
  TempDir dir;
  for (const char* name : {"cagd86", "tp4-d3", "tp4-d6", "dome3-d3", "dome6-d4", "dome7-d3"}) {
    const GBPatch original = read_gbp(reference(name));
    const auto json = dir / (std::string(name) + ".json");
    const auto back = dir / (std::string(name) + ".gbp");
    auto r = cli({"convert", reference(name).string(), "-o", json.string()});
    ASSERT_EQ(r.code, 0) << r.err;
    // The scene holds one gb patch with the points in .gbp order.
    const auto j = nlohmann::json::parse(slurp(json));
    ASSERT_EQ(j["patches"].size(), 1u);
    EXPECT_EQ(j["patches"][0]["type"], "gb");
    EXPECT_EQ(j["patches"][0]["sides"], original.sides());
    EXPECT_EQ(j["patches"][0]["degree"], original.degree());
    ASSERT_EQ(j["patches"][0]["points"].size(), original.size());
    for (std::size_t k = 0; k < original.size(); ++k)
      for (int c = 0; c < 3; ++c)
        ASSERT_EQ(j["patches"][0]["points"][k][c].get<double>(), original.control_point(k)[c]);
    r = cli({"convert", json.string(), "-o", back.string()});
    ASSERT_EQ(r.code, 0) << r.err;
    const GBPatch again = read_gbp(back);
    ASSERT_EQ(again.sides(), original.sides());
    ASSERT_EQ(again.degree(), original.degree());
    for (std::size_t k = 0; k < original.size(); ++k)
      for (int c = 0; c < 3; ++c)  // bit for bit
        ASSERT_EQ(again.control_point(k)[c], original.control_point(k)[c]) << name << " " << k;
    // Converting the written .gbp again reproduces the same text.
    const auto third = dir / (std::string(name) + "-2.gbp");
    ASSERT_EQ(cli({"convert", back.string(), "-o", third.string()}).code, 0);
    EXPECT_EQ(slurp(third), slurp(back));
  }
}

TEST(ConvertGbp, GbpIsAnInputOfExportAndAnalyze) {
  ASSERT_TRUE(std::filesystem::exists(reference("cagd86"))) << "GB reference missing";
  TempDir dir;
  const auto obj = dir / "out.obj";
  auto r = cli({"export", reference("cagd86").string(), "-o", obj.string(), "--density", "8"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(slurp(obj).find("\nv "), std::string::npos);
  r = cli({"analyze", reference("dome6-d4").string(), "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["patches"][0]["type"], "gb");
  EXPECT_EQ(j["patches"][0]["nonfinite_samples"], 0);
  EXPECT_LT(j["patches"][0]["max_boundary_deviation"].get<double>(), 1e-12 * 30);
}

TEST(ConvertGbp, SceneMustHoldExactlyOneGbPatch) {
  TempDir dir;
  const std::string gb =
      R"({"type":"gb","sides":3,"degree":1,"points":[[0,0,1],[1,0,0],[0,1,0],[-1,-1,0]]})";
  const std::string bez =
      R"({"type":"bezier","degree":[1,1],"points":[[0,0,0],[0,1,0],[1,0,0],[1,1,0]]})";
  struct Case {
    std::string scene, expect;
  } cases[] = {
      {R"({"patchlab":1})", "0 explicit patches"},
      {R"({"patchlab":1,"patches":[)" + gb + "," + gb + "]}", "2 explicit patches"},
      {R"({"patchlab":1,"patches":[)" + bez + "]}", "patches[0]"},
  };
  for (const Case& c : cases) {
    const auto in = dir.file("scene.json", c.scene);
    const auto out = dir / "out.gbp";
    const auto r = cli({"convert", in.string(), "-o", out.string()});
    EXPECT_EQ(r.code, 1) << c.scene;
    EXPECT_NE(r.err.find(in.string()), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(c.expect), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(out));
  }
  // One gb patch converts, and the .gbp reads back as the same patch.
  const auto in = dir.file("one.json", R"({"patchlab":1,"patches":[)" + gb + "]}");
  ASSERT_EQ(cli({"convert", in.string(), "-o", (dir / "one.gbp").string()}).code, 0);
  EXPECT_EQ(slurp(dir / "one.gbp"), "3 1\n0 0 1\n1 0 0\n0 1 0\n-1 -1 0\n");
  EXPECT_EQ(cli({"convert", in.string(), "-o", (dir / "x.obj").string()}).code, 2);
  EXPECT_EQ(cli({"convert", in.string()}).code, 2);
}

TEST(ConvertGbp, MalformedGbpNamesFileAndToken) {
  const std::string pts3 = " 0 0 1  1 0 0  0 1 0  -1 -1 0";  // n = 3, d = 1: 4 points
  struct Case {
    const char* what;
    std::string text, token;
  } cases[] = {
      {"empty file", "", "token 1"},
      {"non-integer n", "three 1" + pts3, "token 1"},
      {"fractional n", "3.5 1" + pts3, "token 1"},
      {"n < 3", "2 1" + pts3, "token 1"},
      {"missing d", "3", "token 2"},
      {"non-integer d", "3 x" + pts3, "token 2"},
      {"d < 1", "3 0" + pts3, "token 2"},
      {"too few points", "3 1 0 0 1  1 0 0  0 1 0  -1 -1", "token 14"},
      {"extra token", "3 1" + pts3 + " 7", "token 15"},
      {"nan", "3 1 0 0 nan  1 0 0  0 1 0  -1 -1 0", "token 5"},
      {"inf", "3 1 0 0 1  1 inf 0  0 1 0  -1 -1 0", "token 7"},
      {"overflow", "3 1 0 0 1  1 0 0  0 1e999 0  -1 -1 0", "token 10"},
      {"not a number", "3 1 0 0 1  1 0 0  0 1 0  -1 -1 zero", "token 14"},
  };
  TempDir dir;
  for (const Case& c : cases) {
    const auto in = dir.file("bad.gbp", c.text);
    for (const std::vector<std::string>& args :
         {std::vector<std::string>{"convert", in.string(), "-o", (dir / "out.json").string()},
          std::vector<std::string>{"export", in.string(), "-o", (dir / "out.obj").string()}}) {
      const auto r = cli(args);
      EXPECT_EQ(r.code, 1) << c.what;
      EXPECT_NE(r.err.find(in.string() + ": " + c.token + ":"), std::string::npos)
          << c.what << ": " << r.err;
      EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    }
    EXPECT_FALSE(std::filesystem::exists(dir / "out.json")) << c.what;
    EXPECT_FALSE(std::filesystem::exists(dir / "out.obj")) << c.what;
  }
  const auto good = dir.file("good.gbp", "3 1" + pts3);
  EXPECT_EQ(cli({"convert", good.string(), "-o", (dir / "out.json").string()}).code, 0);
}

}  // namespace
}  // namespace pl::test
