// The ribbon schemes on the command line: a scene with a `ribbons` patch and network faces with
// every scheme evaluate (exit 0); the bad scenes of the ribbon schemes (a wrong side count,
// incompatible corners, an unknown scheme, a concave face for a scheme that needs a convex one)
// give exit 1 with one message naming the file and the place.
#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>

#include "cli_test_util.hpp"
#include "core/scene/network_edit.hpp"

namespace pl::test {
namespace {

// A unit square face with a bulging middle: straight sides, cross derivatives that lift the
// middle of each side's ribbon (their ends are the neighbouring sides' tangents).
std::string ribbon_side(const char* curve, const char* cross) {
  return std::string(R"({"curve":{"type":"bezier","points":)") + curve +
         R"(},"cross":{"type":"bezier","points":)" + cross + "}}";
}
std::string square_sides(const char* side1_cross = "[[-1,0,0],[-1,0,1],[-1,0,0]]") {
  // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on "[" + std::string.
  std::string out = "[";
  out += ribbon_side("[[0,0,0],[0.3333333333333333,0,0],[0.6666666666666666,0,0],[1,0,0]]",
                     "[[0,1,0],[0,1,1],[0,1,0]]");
  out += ",";
  out += ribbon_side("[[1,0,0],[1,0.3333333333333333,0],[1,0.6666666666666666,0],[1,1,0]]",
                     side1_cross);
  out += ",";
  out += ribbon_side("[[1,1,0],[0.6666666666666666,1,0],[0.3333333333333333,1,0],[0,1,0]]",
                     "[[0,-1,0],[0,-1,1],[0,-1,0]]");
  out += ",";
  out += ribbon_side("[[0,1,0],[0,0.6666666666666666,0],[0,0.3333333333333333,0],[0,0,0]]",
                     "[[1,0,0],[1,0,1],[1,0,0]]");
  return out + "]";
}
std::string ribbons_scene(const std::string& scheme, const std::string& sides,
                          const std::string& extra = "") {
  return R"({"patchlab":1,"patches":[{"type":"ribbons","scheme":")" + scheme + R"(","sides":)" +
         sides + extra + "}]}";
}

std::string asset(const char* name) {
  return slurp(std::filesystem::path(PATCHLAB_SOURCE_DIR) / "assets" / name);
}

TEST(RibbonSchemeCli, ARibbonsPatchOfEverySchemeIsAnalysedAndExported) {
  TempDir dir;
  for (FaceScheme s : all_face_schemes()) {
    if (!is_ribbon_scheme(s)) continue;
    const auto file = dir.file("r.json", ribbons_scene(scheme_keyword(s), square_sides()));
    const CliResult a = cli({"analyze", file.string(), "--json"});
    EXPECT_EQ(a.code, kExitOk) << scheme_keyword(s) << ": " << a.err;
    const CliResult e = cli({"export", file.string(), "-o", (dir / "r.obj").string()});
    EXPECT_EQ(e.code, kExitOk) << scheme_keyword(s) << ": " << e.err;
    EXPECT_TRUE(std::filesystem::exists(dir / "r.obj"));
  }
}

TEST(RibbonSchemeCli, EveryFaceSchemeFillsTheSampleNetworks) {
  TempDir dir;
  for (const char* name : {"default.json", "gb-hole-filling.json", "gregory-blob-closed.json"}) {
    const auto file = dir.file("n.json", asset(name));
    for (FaceScheme s : all_face_schemes()) {
      const CliResult r = cli({"analyze", file.string(), "--scheme", scheme_keyword(s)});
      EXPECT_EQ(r.code, kExitOk) << name << " " << scheme_keyword(s) << ": " << r.err;
    }
  }
}

struct BadScene {
  const char* what;
  std::string json;
  std::vector<std::string> options;
  std::vector<const char*> expect;  // every one must be in the message
};

std::vector<BadScene> bad_scenes() {
  nlohmann::json concave = nlohmann::json::parse(asset("gb-concave-l.json"));
  concave["network"]["faces"][0]["scheme"] = "side-based";  // the L-shaped hexagon
  nlohmann::json unknown = nlohmann::json::parse(asset("default.json"));
  unknown["network"]["faces"][1]["scheme"] = "coons";
  std::string two_sides = "[";
  two_sides += ribbon_side("[[0,0,0],[1,0,0]]", "[[0,1,0],[0,1,0]]");
  two_sides += ",";
  two_sides += ribbon_side("[[1,0,0],[0,0,0]]", "[[0,-1,0],[0,-1,0]]");
  two_sides += "]";
  return {
      {"ribbons patch with 2 sides",
       ribbons_scene("midpoint", two_sides),
       {},
       {"patches[0].sides", "3 to 64 sides, this one has 2"}},
      {"incompatible corner",
       ribbons_scene("corner-based", square_sides("[[-1,0,0.5],[-1,0,1],[-1,0,0]]")),
       {},
       {"patches[0]", "corner 0 (end of side 0, start of side 1)"}},
      {"unknown ribbons scheme",
       ribbons_scene("kato", square_sides()),
       {},
       {"patches[0].scheme", "unknown scheme \"kato\""}},
      {"midpoint of a scheme without one",
       ribbons_scene("side-based", square_sides(), R"(,"midpoint":[0,0,1])"),
       {},
       {"patches[0].midpoint"}},
      {"unknown face scheme", unknown.dump(), {}, {"network.faces[1].scheme", "unknown scheme"}},
      {"concave face with a ribbon scheme",
       concave.dump(),
       {},
       {"network.faces[0]", "side-based", "reflex"}},
      {"concave face under --scheme",
       asset("gb-concave-l.json"),
       {"--scheme", "midpoint"},
       {"network.faces[0]", "midpoint", "reflex"}},
  };
}

TEST(RibbonSchemeCli, BadScenesGiveExitOneWithOneLocatedMessage) {
  TempDir dir;
  for (const BadScene& c : bad_scenes()) {
    const auto file = dir.file("bad.json", c.json);
    for (const char* cmd : {"analyze", "export"}) {
      std::vector<std::string> args{cmd, file.string()};
      if (std::string(cmd) == "export") args.insert(args.end(), {"-o", (dir / "o.obj").string()});
      args.insert(args.end(), c.options.begin(), c.options.end());
      const CliResult r = cli(args);
      EXPECT_EQ(r.code, kExitBadInput) << c.what << "\n" << r.err;
      EXPECT_NE(r.err.find(file.string()), std::string::npos) << c.what << ": " << r.err;
      for (const char* part : c.expect)
        EXPECT_NE(r.err.find(part), std::string::npos) << c.what << ": message was " << r.err;
      EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one message: " << r.err;
      EXPECT_FALSE(std::filesystem::exists(dir / "o.obj")) << c.what;
    }
  }
  EXPECT_EQ(cli({"analyze", "a.json", "--scheme", "kato"}).code, kExitUsage);
}

}  // namespace
}  // namespace pl::test
