// The CLI honours the interior control of GB faces: analyze reports each GB face's degree and
// how many free points carry offsets, and the shared edges stay G1; export writes the edited
// surface.
#include <gtest/gtest.h>

#include "cli_test_util.hpp"

namespace pl {
namespace {

const std::string kScene = std::string(PATCHLAB_SOURCE_DIR) + "/assets/gb-interior.json";

TEST(InteriorCli, AnalyzeReportsDegreeOffsetsAndG1) {
  const test::CliResult r = test::cli({"analyze", kScene, "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  bool pentagon = false;
  for (const auto& p : j["patches"]) {
    if (p["name"] == "pentagon") {
      pentagon = true;
      EXPECT_EQ(p["degree"], 5);
      EXPECT_EQ(p["offsets"], 2);
    }
    if (p["name"] == "hexagon") {  // a GB face without interior control
      EXPECT_EQ(p["degree"], 3);
      EXPECT_EQ(p["offsets"], 0);
    }
    if (p["type"].get<std::string>().rfind("gb-ribbons", 0) != 0) {  // gb-ribbons(-interior)
      EXPECT_FALSE(p.contains("degree"));
    }
    EXPECT_LT(p["max_boundary_deviation"].get<double>(), 1e-12);
  }
  EXPECT_TRUE(pentagon);
  ASSERT_FALSE(j["edges"].empty());
  for (const auto& e : j["edges"]) EXPECT_LT(e["max_normal_angle_deg"].get<double>(), 1e-6);
}

TEST(InteriorCli, ExportShowsTheEditedInterior) {
  test::TempDir dir;
  const std::string plain = std::string(PATCHLAB_SOURCE_DIR) + "/assets/gb-hole-filling.json";
  ASSERT_EQ(test::cli({"export", kScene, "-o", (dir / "a.obj").string()}).code, 0);
  ASSERT_EQ(test::cli({"export", plain, "-o", (dir / "b.obj").string()}).code, 0);
  // The raised centre lifts the pentagon (same tessellation): its mean height grows.
  const auto mean_z = [](const std::string& obj) {
    std::istringstream in(obj);
    std::string line, object;
    double z = 0;
    int count = 0;
    while (std::getline(in, line)) {
      if (line.rfind("o ", 0) == 0) object = line.substr(2);
      if (object == "pentagon" && line.rfind("v ", 0) == 0) {
        std::istringstream v(line.substr(2));
        double x, y, zz;
        v >> x >> y >> zz;
        z += zz;
        ++count;
      }
    }
    return count ? z / count : 0.0;
  };
  EXPECT_GT(mean_z(test::slurp(dir / "a.obj")), mean_z(test::slurp(dir / "b.obj")) + 0.01);
}

}  // namespace
}  // namespace pl
