// `patchlab compare`: the figures of every scheme over the default scene's faces, as a table and
// as the documented JSON; a scheme that cannot fill a face is reported per face; bad options and
// bad bases follow the CLI's exit rules with one message.
#include <gtest/gtest.h>

#include <algorithm>

#include "cli_test_util.hpp"
#include "core/analysis/compared_schemes.hpp"
#include "core/scene/network_edit.hpp"

namespace pl::test {
namespace {

const std::string kDefault = PATCHLAB_SOURCE_DIR "/assets/default.json";

int lines_starting(const std::string& text, const std::string& prefix) {
  int n = 0;
  std::size_t at = 0;
  while (at < text.size()) {
    if (text.compare(at, prefix.size(), prefix) == 0) ++n;
    const std::size_t next = text.find('\n', at);
    if (next == std::string::npos) break;
    at = next + 1;
  }
  return n;
}

TEST(CompareCommand, JsonListsEverySchemeOfEveryFace) {
  const CliResult r = cli({"compare", kDefault, "--density", "12", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["base"], "gb");
  ASSERT_EQ(j["faces"].size(), 2u);
  EXPECT_EQ(j["faces"][0]["face"], "quad");
  EXPECT_EQ(j["faces"][0]["sides"], 4);
  EXPECT_EQ(j["faces"][1]["face"], "pentagon");
  EXPECT_EQ(j["faces"][1]["sides"], 5);
  for (const auto& face : j["faces"]) {
    EXPECT_EQ(face["schemes"].size(), comparable_schemes().size());
    for (const auto& [name, f] : face["schemes"].items()) {
      if (f.contains("cannot_fill")) continue;
      EXPECT_LT(f["max_normal_angle_deg"].get<double>(), 1e-6) << name;
      EXPECT_LT(f["max_boundary_deviation"].get<double>(), 1e-12) << name;
      EXPECT_LE(f["mean_curvature"][0].get<double>(), f["mean_curvature"][1].get<double>());
      EXPECT_GT(f["area"].get<double>(), 0) << name;
      EXPECT_GT(f["bending_energy"].get<double>(), 0) << name;
      EXPECT_GT(f["msamples_per_s"].get<double>(), 0) << name;
    }
  }
  // The base against itself.
  EXPECT_EQ(j["faces"][0]["schemes"]["gb"]["max_distance_to_base"], 0.0);
  // Gregory takes 3 and 4 sides only: the pentagon says so, the quad has its figures.
  EXPECT_NE(j["faces"][1]["schemes"]["gregory"]["cannot_fill"].get<std::string>().find(
                "a Gregory patch has 3 or 4"),
            std::string::npos);
  EXPECT_GT(j["faces"][0]["schemes"]["gregory"]["max_distance_to_base"].get<double>(), 0);
}

TEST(CompareCommand, TablePerFaceWithChosenSchemesBaseAndFaces) {
  const CliResult r = cli({"compare", kDefault, "--schemes", "gb,gregory", "--base", "gregory",
                           "--faces", "quad", "--density", "8"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("face quad (4 sides), density 8, distances to gregory"), std::string::npos)
      << r.out;
  EXPECT_EQ(r.out.find("pentagon"), std::string::npos) << r.out;
  EXPECT_EQ(lines_starting(r.out, "  gb "), 1) << r.out;
  EXPECT_EQ(lines_starting(r.out, "  gregory "), 1) << r.out;
  // Faces by index too; a scheme that cannot fill the face is one clear line.
  const CliResult p = cli({"compare", kDefault, "--faces", "1", "--density", "8"});
  ASSERT_EQ(p.code, 0) << p.err;
  EXPECT_NE(p.out.find("gregory            cannot fill this face: "), std::string::npos) << p.out;
}

TEST(CompareCommand, BadUsageAndBadInputGiveOneMessage) {
  const CliResult unknown = cli({"compare", kDefault, "--schemes", "gb,coons-ish"});
  EXPECT_EQ(unknown.code, 2);
  EXPECT_EQ(lines_starting(unknown.err, "patchlab: "), 1) << unknown.err;
  EXPECT_NE(unknown.err.find("patchlab: --schemes: unknown scheme \"coons-ish\" (allowed: " +
                             comparable_scheme_keywords() + ")"),
            std::string::npos)
      << unknown.err;
  EXPECT_EQ(cli({"compare", kDefault, "--base", "auto"}).code, 2);
  EXPECT_EQ(cli({"compare", kDefault, "--schemes", "gb,,gregory"}).code, 2);
  EXPECT_EQ(cli({"compare"}).code, 2);
  EXPECT_EQ(cli({"compare", kDefault, "--density", "0"}).code, 2);

  const CliResult base = cli({"compare", kDefault, "--base", "gregory"});
  EXPECT_EQ(base.code, 1);
  EXPECT_EQ(lines_starting(base.err, "patchlab: "), 1) << base.err;
  EXPECT_NE(base.err.find("default.json: network.faces[1]: the base scheme gregory cannot fill "
                          "face \"pentagon\""),
            std::string::npos)
      << base.err;

  const CliResult face = cli({"compare", kDefault, "--faces", "hexagon"});
  EXPECT_EQ(face.code, 1);
  EXPECT_NE(face.err.find("no face named or numbered \"hexagon\""), std::string::npos) << face.err;

  const TempDir dir;
  const auto patch_only =
      dir.file("patch.json",
               R"({"patchlab": 1, "patches": [{"type": "bezier", "degree": [1, 1],
          "points": [[0,0,0],[0,1,0],[1,0,0],[1,1,0]]}]})");
  const CliResult none = cli({"compare", patch_only.string()});
  EXPECT_EQ(none.code, 1);
  EXPECT_NE(none.err.find("network: the scene has no network faces to compare"), std::string::npos)
      << none.err;
}

}  // namespace
}  // namespace pl::test
