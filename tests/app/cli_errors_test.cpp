// Every kind of malformed input the scene spec names gives exit code 1 and one message naming the
// file and the JSON path; wrong usage gives exit code 2. None crashes (this suite also runs under
// AddressSanitizer and UndefinedBehaviorSanitizer).
#include <gtest/gtest.h>

#include "cli_test_util.hpp"

namespace pl::test {
namespace {

const char* kGoodNetwork = R"({"patchlab": 1, "network": {
  "vertices": [[0,0,0],[1,0,0],[1,1,0],[0,1,0]],
  "edges": [{"v":[0,1],"handles":[[0.3,0,0],[0.6,0,0]]},{"v":[1,2],"handles":[[1,0.3,0],[1,0.6,0]]},
            {"v":[2,3],"handles":[[0.6,1,0],[0.3,1,0]]},{"v":[3,0],"handles":[[0,0.6,0],[0,0.3,0]]}],
  "faces": [{"loop":[0,1,2,3]}]}})";

struct BadCase {
  const char* what;
  std::string json;
  const char* expect_in_message;  // the JSON path (or line) the message must name
};

std::vector<BadCase> bad_cases() {
  const std::string bez =
      R"({"type":"bezier","degree":[1,1],"points":[[0,0,0],[0,1,0],[1,0,0],[1,1,0]]})";
  return {
      {"syntax error", R"({"patchlab": 1,)", "line 1"},
      {"not an object", "[1,2]", "(top level)"},
      {"missing version", R"({"name":"x"})", "patchlab"},
      {"wrong version", R"({"patchlab": 2})", "patchlab: unsupported format version 2"},
      {"unknown top-level key", R"({"patchlab":1,"colour":3})", "colour: unknown key"},
      {"wrong type of name", R"({"patchlab":1,"name":5})", "name: expected a string"},
      {"unknown patch type", R"({"patchlab":1,"patches":[{"type":"teapot"}]})", "patches[0].type"},
      {"wrong degree length",
       R"({"patchlab":1,"patches":[{"type":"bezier","degree":[1],"points":[]}]})",
       "patches[0].degree"},
      {"too few points",
       R"({"patchlab":1,"patches":[{"type":"bezier","degree":[1,1],"points":[[0,0,0]]}]})",
       "patches[0].points"},
      {"point of length 2",
       R"({"patchlab":1,"patches":[{"type":"bezier","degree":[1,1],"points":[[0,0],[0,1,0],[1,0,0],[1,1,0]]}]})",
       "patches[0].points[0]"},
      {"string coordinate",
       R"({"patchlab":1,"patches":[{"type":"bezier","degree":[1,1],"points":[[0,0,"a"],[0,1,0],[1,0,0],[1,1,0]]}]})",
       "patches[0].points[0][2]"},
      {"non-finite number (overflow)",
       R"({"patchlab":1,"patches":[{"type":"bezier","degree":[1,1],"points":[[0,0,1e999],[0,1,0],[1,0,0],[1,1,0]]}]})",
       "patches[0].points[0][2]"},
      {"negative degree",
       R"({"patchlab":1,"patches":[{"type":"bezier","degree":[-1,1],"points":[]}]})",
       "patches[0].degree[0]"},
      {"fractional degree",
       R"({"patchlab":1,"patches":[{"type":"bezier","degree":[1.5,1],"points":[]}]})",
       "patches[0].degree[0]"},
      {"unknown patch key",
       R"({"patchlab":1,"patches":[)" + bez.substr(0, bez.size() - 1) + R"(,"w":1}]})",
       "patches[0].w"},
      {"edge vertex out of range",
       R"({"patchlab":1,"network":{"vertices":[[0,0,0],[1,0,0]],"edges":[{"v":[0,5],"handles":[[0,0,0],[1,0,0]]}]}})",
       "network.edges[0].v[1]"},
      {"loop vertex out of range",
       R"({"patchlab":1,"network":{"vertices":[[0,0,0],[1,0,0],[0,1,0]],"faces":[{"loop":[0,1,17]}]}})",
       "network.faces[0].loop[2]: vertex 17 does not exist (3 vertices)"},
      {"loop without edge",
       R"({"patchlab":1,"network":{"vertices":[[0,0,0],[1,0,0],[0,1,0]],"edges":[],"faces":[{"loop":[0,1,2]}]}})",
       "network.faces[0].loop[0]: no edge joins vertices 0 and 1"},
      {"loop too short",
       R"({"patchlab":1,"network":{"vertices":[[0,0,0],[1,0,0]],"edges":[{"v":[0,1],"handles":[[0,0,0],[1,0,0]]}],"faces":[{"loop":[0,1]}]}})",
       "network.faces[0].loop"},
      {"repeated loop vertex",
       R"({"patchlab":1,"network":{"vertices":[[0,0,0],[1,0,0],[0,1,0]],"faces":[{"loop":[0,1,0]}]}})",
       "network.faces[0].loop[2]"},
      {"gregory scheme on a pentagon",
       R"({"patchlab":1,"network":{"vertices":[[0,0,0],[1,0,0],[0,1,0],[2,2,0],[3,3,0]],"faces":[{"loop":[0,1,2,3,4],"scheme":"gregory"}]}})",
       "network.faces[0].scheme"},
      {"duplicate edge",
       R"({"patchlab":1,"network":{"vertices":[[0,0,0],[1,0,0]],"edges":[{"v":[0,1],"handles":[[0,0,0],[1,0,0]]},{"v":[1,0],"handles":[[0,0,0],[1,0,0]]}]}})",
       "network.edges[1].v"},
      {"normals of wrong length",
       R"({"patchlab":1,"network":{"vertices":[[0,0,0],[1,0,0]],"normals":[[0,0,1]]}})",
       "network.normals"},
      {"zero normal", R"({"patchlab":1,"network":{"vertices":[[0,0,0]],"normals":[[0,0,0]]}})",
       "network.normals[0]"},
      {"same-direction shared edge",
       [] {
         std::string s = kGoodNetwork;
         // A second face over the same square in the same direction.
         s.replace(s.find("}]}}"), 4, "},{\"loop\":[0,1,2,3]}]}}");
         return s;
       }(),
       "network.faces[1].loop[0]"},
  };
}

TEST(CliErrors, EveryMalformedSceneGivesExitOneAndNamesFileAndPath) {
  TempDir dir;
  for (const BadCase& c : bad_cases()) {
    const auto file = dir.file("bad.json", c.json);
    for (const char* cmd : {"analyze", "export"}) {
      std::vector<std::string> args{cmd, file.string()};
      if (std::string(cmd) == "export") args.insert(args.end(), {"-o", (dir / "o.obj").string()});
      const CliResult r = cli(args);
      EXPECT_EQ(r.code, kExitBadInput) << c.what << "\n" << r.err;
      EXPECT_NE(r.err.find(file.string()), std::string::npos) << c.what << ": " << r.err;
      EXPECT_NE(r.err.find(c.expect_in_message), std::string::npos)
          << c.what << ": message was " << r.err;
      EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one message: " << r.err;
      EXPECT_FALSE(std::filesystem::exists(dir / "o.obj")) << c.what;
    }
  }
}

TEST(CliErrors, UnreadableFileAndWrongUsage) {
  TempDir dir;
  CliResult r = cli({"analyze", (dir / "missing.json").string()});
  EXPECT_EQ(r.code, kExitBadInput);
  EXPECT_NE(r.err.find("missing.json"), std::string::npos);
  // A FILE that is neither .json nor .gbp: the command line alone shows it (docs/cli.md).
  r = cli({"analyze", dir.file("x.txt", "hello").string()});
  EXPECT_EQ(r.code, kExitUsage);
  EXPECT_EQ(cli({"frobnicate"}).code, kExitUsage);
  EXPECT_EQ(cli({"analyze"}).code, kExitUsage);
  EXPECT_EQ(cli({"analyze", "a.json", "--density", "0"}).code, kExitUsage);
  EXPECT_EQ(cli({"analyze", "a.json", "--density", "12x"}).code, kExitUsage);
  EXPECT_EQ(cli({"analyze", "a.json", "--scheme", "coons"}).code, kExitUsage);
  EXPECT_EQ(cli({"export", "a.json"}).code, kExitUsage);
  EXPECT_EQ(cli({"analyze", "a.json", "--bogus"}).code, kExitUsage);
  r = cli({"--version"});
  EXPECT_EQ(r.code, kExitOk);
  EXPECT_NE(r.out.find("patchlab "), std::string::npos);
  r = cli({"--help"});
  EXPECT_EQ(r.code, kExitOk);
  EXPECT_NE(r.out.find("export"), std::string::npos);
}

TEST(CliErrors, FailedExportKeepsThePreviousFile) {
  TempDir dir;
  const auto out = dir.file("keep.obj", "previous content\n");
  const auto bad = dir.file("bad.json", R"({"patchlab": 1, "patches": [{"type": "bezier"}]})");
  EXPECT_EQ(cli({"export", bad.string(), "-o", out.string()}).code, kExitBadInput);
  EXPECT_EQ(slurp(out), "previous content\n");
  // Unwritable target directory: error, not a crash.
  const auto good = dir.file(
      "good.json",
      R"({"patchlab":1,"patches":[{"type":"bezier","degree":[1,1],"points":[[0,0,0],[0,1,0],[1,0,0],[1,1,0]]}]})");
  const CliResult r = cli({"export", good.string(), "-o", (dir / "no/such/dir/x.obj").string()});
  EXPECT_EQ(r.code, kExitBadInput) << r.err;
}

}  // namespace
}  // namespace pl::test
