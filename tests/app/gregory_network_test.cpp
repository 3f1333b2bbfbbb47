// `patchlab analyze --json` and `export` on the Gregory sample scenes: network faces filled
// with Gregory patches interpolate the edges and join G1 (figures from the exact derivatives
// the CLI evaluates), and the export writes every face with exact normals.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cli_test_util.hpp"

namespace pl::test {
namespace {

std::string asset(const std::string& name) {
  return std::string(PATCHLAB_SOURCE_DIR) + "/assets/" + name;
}

struct Expect {
  const char* file;
  std::size_t faces, shared_edges;
};

class GregoryScenes : public ::testing::TestWithParam<Expect> {};

TEST_P(GregoryScenes, AnalyzeReportsInterpolationAndG1) {
  const Expect e = GetParam();
  const CliResult r = cli({"analyze", asset(e.file), "--json", "--density", "16"});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["patches"].size(), e.faces);
  double deviation = 0;
  for (const auto& p : j["patches"]) {
    deviation = std::max(deviation, p["max_boundary_deviation"].get<double>());
    const int sides = p["sides"];
    EXPECT_EQ(p["type"], sides == 3 ? "gregory-tri" : "gregory-quad");
    EXPECT_LT(p["max_boundary_deviation"].get<double>(), 1e-12);  // the scenes are ~3 units
    EXPECT_EQ(p["nonfinite_samples"], 0);
  }
  ASSERT_EQ(j["edges"].size(), e.shared_edges);
  double worst = 0;
  for (const auto& ed : j["edges"]) {
    EXPECT_LT(ed["max_gap"].get<double>(), 1e-12);
    worst = std::max(worst, ed["max_normal_angle_deg"].get<double>());
  }
  std::printf("figure %s_max_boundary_deviation %.3g\nfigure %s_max_normal_angle_deg %.3g\n",
              e.file, deviation, e.file, worst);
  EXPECT_LT(worst, 1e-6);
  EXPECT_TRUE(j["vertices"].empty());  // every vertex's end tangents are coplanar
}

TEST_P(GregoryScenes, ExportWritesEveryFaceWithUnitNormals) {
  const Expect e = GetParam();
  TempDir dir;
  const auto obj = dir / "out.obj";
  const CliResult r = cli({"export", asset(e.file), "-o", obj.string(), "--density", "8"});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  std::istringstream in(slurp(obj));
  std::size_t objects = 0, vn = 0, v = 0;
  for (std::string line; std::getline(in, line);) {
    std::istringstream ls(line);
    std::string tag;
    ls >> tag;
    if (tag == "o") ++objects;
    if (tag == "v") ++v;
    if (tag == "vn") {
      double x, y, z;
      ls >> x >> y >> z;
      EXPECT_NEAR(std::sqrt(x * x + y * y + z * z), 1, 1e-6);
      ++vn;
    }
  }
  EXPECT_EQ(objects, e.faces);
  EXPECT_EQ(vn, v);
  EXPECT_GT(v, 0u);
}

// Every network scene of assets/, as written and with --scheme gregory: the Gregory faces
// among them interpolate their edges and are finite everywhere.
TEST(GregoryScenes, GregoryFacesOfEveryNetworkAssetAreFiniteAndInterpolate) {
  int gregory_faces = 0;
  for (const auto& entry : std::filesystem::directory_iterator(asset(""))) {
    if (entry.path().extension() != ".json") continue;
    const std::string text = slurp(entry.path());
    if (text.find("\"network\"") == std::string::npos) continue;
    for (const bool override_scheme : {false, true}) {
      std::vector<std::string> args{"analyze", entry.path().string(), "--json", "--density", "8"};
      if (override_scheme) args.insert(args.end(), {"--scheme", "gregory"});
      const CliResult r = cli(args);
      ASSERT_EQ(r.code, kExitOk) << entry.path() << r.err;
      const auto report = nlohmann::json::parse(r.out);
      for (const auto& p : report["patches"]) {
        if (p["type"].get<std::string>().rfind("gregory", 0) != 0) continue;
        ++gregory_faces;
        EXPECT_EQ(p["nonfinite_samples"], 0) << entry.path();
        EXPECT_LT(p["max_boundary_deviation"].get<double>(), 1e-11) << entry.path();
      }
    }
  }
  EXPECT_GT(gregory_faces, 22);  // at least the two Gregory scenes' faces
}

// 12 faces, 21 edges all shared (closed); 10 faces, 20 edges of which 15 shared (open).
INSTANTIATE_TEST_SUITE_P(Assets, GregoryScenes,
                         ::testing::Values(Expect{"gregory-blob-closed.json", 12, 21},
                                           Expect{"gregory-cap-open.json", 10, 15}));

}  // namespace
}  // namespace pl::test
