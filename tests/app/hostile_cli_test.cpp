// The hostile-input reproducers through the command line: each exits 1 with one located message,
// or 0 with finite output. Some run the real binary, to see what reaches its stderr (OpenMesh
// printed its own lines there) and how it dies (OpenMesh aborted it; SIGKILL leaves temporaries).
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstring>

#include "cli_test_util.hpp"
#include "core/math/vec.hpp"

namespace pl::test {
namespace {

const std::string kAssets = PATCHLAB_SOURCE_DIR "/assets/";

// The binary run with a shell command line; its exit status and all it printed.
struct Ran {
  int code;
  std::string output;
};
Ran run_binary(const std::string& args) {
  const std::string cmd = std::string(PATCHLAB_BINARY) + " " + args + " 2>&1";
  std::FILE* p = popen(cmd.c_str(), "r");
  std::string out;
  char buf[4096];
  while (std::size_t n = std::fread(buf, 1, sizeof buf, p)) out.append(buf, n);
  const int status = pclose(p);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status), out};
}

std::size_t lines(const std::string& s) {
  return std::count(s.begin(), s.end(), '\n');
}

std::vector<Vec3> obj_normals(const std::string& obj) {
  std::vector<Vec3> r;
  std::istringstream in(obj);
  std::string tag;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("vn ", 0) != 0) continue;
    Vec3 n;
    std::istringstream(line) >> tag >> n.x >> n.y >> n.z;
    r.push_back(n);
  }
  return r;
}

TEST(HostileCli, CatmullClarkRepeatedVertexExitsOneWithOneLine) {
  TempDir dir;
  for (const char* faces : {"[[0,0,1,2,3]]", "[[0,1,2,3,3]]", "[[0,1,0,2,3]]"}) {
    const auto f = dir.file(
        "cc.json", std::string(R"({"patchlab":1,"patches":[{"type":"catmull-clark",)") +
                       R"("vertices":[[0,0,0],[1,0,0],[1,1,0],[0,1,0]],"faces":)" + faces + "}]}");
    for (const std::string& cmd :
         {"analyze " + f.string(), "export " + f.string() + " -o " + (dir / "o.obj").string()}) {
      const Ran r = run_binary(cmd);
      EXPECT_EQ(r.code, 1) << cmd << "\n" << r.output;  // was 134: OpenMesh's assertion
      EXPECT_EQ(lines(r.output), 1u) << r.output;
      EXPECT_NE(r.output.find("patches[0].faces[0]: face 0 repeats vertex"), std::string::npos)
          << r.output;
    }
  }
}

TEST(HostileCli, OpenMeshPrintsNothingBeforeOurMessage) {
  TempDir dir;
  // Two triangles traversing the edge 1->2 the same way: OpenMesh's "complex edge".
  const auto f = dir.file("flip.json", R"({"patchlab":1,"patches":[{"type":"catmull-clark",
      "vertices":[[0,0,0],[1,0,0],[1,1,0],[2,1,0]],"faces":[[0,1,2],[1,2,3]]}]})");
  const Ran r = run_binary("analyze " + f.string());
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(lines(r.output), 1u) << r.output;
  EXPECT_EQ(r.output.rfind("patchlab: ", 0), 0u) << r.output;
}

TEST(HostileCli, OverflowingCoordinatesAreRefusedUpFront) {
  TempDir dir;
  auto wave = nlohmann::json::parse(slurp(kAssets + "bezier-wave.json"));
  wave["patches"][0]["points"][5][2] = 1e308;
  const auto f = dir.file("wave.json", wave.dump());
  for (const char* cmd : {"export", "analyze"}) {
    std::vector<std::string> args = {cmd, f.string()};
    if (std::string(cmd) == "export") args.insert(args.end(), {"-o", (dir / "w.obj").string()});
    const CliResult r = cli(args);
    EXPECT_EQ(r.code, kExitBadInput) << cmd;
    EXPECT_NE(r.err.find("patches[0].points[5][2]: coordinate 1e+308 is out of range"),
              std::string::npos)
        << r.err;
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "w.obj"));
  const auto g = dir.file("t.gbp", "3 1\n0 0 0\n1 0 0\n0 1 1e308\n1 1 0\n");
  const CliResult r = cli({"export", g.string(), "-o", (dir / "g.obj").string()});
  EXPECT_EQ(r.code, kExitBadInput);
  EXPECT_NE(r.err.find("token 11: coordinate"), std::string::npos) << r.err;
  // At scale 1e300 the message said a handle coincides with its vertex; it is the scale.
  const auto big = dir.file(
      "big.json", scaled(nlohmann::json::parse(slurp(kAssets + "default.json")), 1e300).dump());
  const CliResult b = cli({"analyze", big.string()});
  EXPECT_EQ(b.code, kExitBadInput);
  EXPECT_NE(b.err.find("is out of range"), std::string::npos) << b.err;
  EXPECT_EQ(b.err.find("coincides"), std::string::npos) << b.err;
}

TEST(HostileCli, TheDefaultSceneAtExtremeScalesHasItsOwnUnitNormals) {
  TempDir dir;
  const auto scene = nlohmann::json::parse(slurp(kAssets + "default.json"));
  const auto f1 = dir.file("one.json", scene.dump());
  ASSERT_EQ(cli({"export", f1.string(), "-o", (dir / "one.obj").string()}).code, kExitOk);
  const std::vector<Vec3> ref = obj_normals(slurp(dir / "one.obj"));
  ASSERT_GT(ref.size(), 1000u);
  for (double s : {1e150, 1e-150}) {
    const auto f = dir.file("s.json", scaled(scene, s).dump());
    const CliResult r = cli({"export", f.string(), "-o", (dir / "s.obj").string()});
    ASSERT_EQ(r.code, kExitOk) << s << r.err;
    const std::vector<Vec3> n = obj_normals(slurp(dir / "s.obj"));
    ASSERT_EQ(n.size(), ref.size());
    double worst = 0;
    for (std::size_t i = 0; i < n.size(); ++i) worst = std::max(worst, glm::length(n[i] - ref[i]));
    EXPECT_LT(worst, 1e-14) << s;  // 3,180 "vn 0 0 0" before
    const CliResult a = cli({"analyze", f.string(), "--json"});
    ASSERT_EQ(a.code, kExitOk) << a.err;
    const auto j = nlohmann::json::parse(a.out);
    for (const auto& p : j["patches"]) {
      EXPECT_EQ(p["singular_samples"], 0) << s;
      EXPECT_TRUE(p["max_boundary_deviation"].is_number());  // not null (inf/NaN)
    }
  }
}

TEST(HostileCli, NurbsSphereStlHasUnitFacetNormalsAtThePoles) {
  TempDir dir;
  const auto out = dir / "nurbs.stl";
  ASSERT_EQ(cli({"export", kAssets + "classic/nurbs.json", "-o", out.string()}).code, kExitOk);
  const std::string stl = slurp(out);
  uint32_t count = 0;
  std::memcpy(&count, stl.data() + 80, 4);
  ASSERT_EQ(stl.size(), 84u + 50u * count);
  std::size_t bad = 0;
  for (uint32_t i = 0; i < count; ++i) {
    float v[12];
    std::memcpy(v, stl.data() + 84 + 50 * i, sizeof v);
    for (float x : v) bad += !std::isfinite(x);
    bad += std::fabs(v[0] * v[0] + v[1] * v[1] + v[2] * v[2] - 1) > 1e-5;
  }
  EXPECT_EQ(bad, 0u);  // 64 NaN facet normals at the poles before
}

TEST(HostileCli, NonFiniteEvaluationFailsNamingPatchAndParameter) {
  // The G2 pair-join construction squares lengths: at scale 1e150 its points overflow.
  TempDir dir;
  const auto f = dir.file(
      "pj.json",
      scaled(nlohmann::json::parse(slurp(kAssets + "classic/pair-join.json")), 1e150).dump());
  for (const std::string ext : {"obj", "ply", "off", "stl"}) {
    const auto out = dir / ("pj." + ext);
    const CliResult r = cli({"export", f.string(), "-o", out.string()});
    EXPECT_EQ(r.code, kExitBadInput) << ext;
    EXPECT_NE(r.err.find(f.string() + ": patch \"g2-pair\" at (u, v) = ("), std::string::npos)
        << r.err;
    EXPECT_FALSE(std::filesystem::exists(out));
  }
  const CliResult a = cli({"analyze", f.string()});
  EXPECT_EQ(a.code, kExitBadInput);  // it counted the non-finite samples and exited 0
  EXPECT_TRUE(a.out.empty());
  EXPECT_NE(a.err.find("patch \"g2-pair\""), std::string::npos) << a.err;
}

TEST(HostileCli, WorkIsBoundedBeforeItStarts) {
  TempDir dir;
  const CliResult d = cli({"analyze", kAssets + "default.json", "--density", "2000"});
  EXPECT_EQ(d.code, kExitBadInput);
  EXPECT_NE(d.err.find("at density 2000 the scene takes about"), std::string::npos) << d.err;
  EXPECT_NE(d.err.find("use --density 10"), std::string::npos) << d.err;
  EXPECT_EQ(cli({"analyze", kAssets + "default.json", "--density", "4097"}).code, kExitUsage);
  // A 10,004-index Catmull-Clark face grew to 3.85 GB before failing without a file name.
  std::string loop, verts;
  for (int i = 0; i < 10004; ++i) {
    if (i) loop += ",", verts += ",";
    loop += std::to_string(i);
    verts += "[";
    verts += std::to_string(std::cos(i * 1e-3));
    verts += ",";
    verts += std::to_string(std::sin(i * 1e-3));
    verts += ",0]";
  }
  const auto f = dir.file("huge.json", R"({"patchlab":1,"patches":[{"type":"catmull-clark",)"
                                       R"("vertices":[)" +
                                           verts + R"(],"faces":[[)" + loop + "]]}]}");
  const CliResult c = cli({"analyze", f.string()});
  EXPECT_EQ(c.code, kExitBadInput);
  EXPECT_NE(c.err.find(f.string() + ": patches[0].faces[0]: a face has at most 256 vertices"),
            std::string::npos)
      << c.err;
}

TEST(HostileCli, WriteErrorsNameTheTargetNotTheTemporaryFile) {
  TempDir dir;
  for (const std::string ext : {"obj", "ply", "off", "stl", "json"}) {
    const std::string target = (dir / "missing" / ("out." + ext)).string();
    const CliResult r = ext == "json" ? cli({"convert", kAssets + "default.json", "-o", target})
                                      : cli({"export", kAssets + "default.json", "-o", target});
    EXPECT_EQ(r.code, kExitBadInput) << ext;
    EXPECT_EQ(r.err, "patchlab: " + target + ": cannot write: no such directory " +
                         (dir / "missing").string() + "\n");
  }
}

TEST(HostileCli, AFileSizeLimitIsReportedNotFatal) {
  // Past ulimit -f the kernel sends SIGXFSZ, which killed the process mid-write and left its
  // temporary file; the CLI ignores it, so the write fails with EFBIG and is reported.
  TempDir dir;
  const auto target = dir / "big.obj";
  const pid_t child = fork();
  if (child == 0) {
    rlimit lim{4096, 4096};
    setrlimit(RLIMIT_FSIZE, &lim);
    const CliResult r = cli({"export", kAssets + "default.json", "-o", target.string()});
    const bool ok =
        r.code == kExitBadInput &&
        r.err.find(target.string() + ": cannot write: file too large") != std::string::npos;
    _exit(ok ? 0 : 1);
  }
  int status = 0;
  waitpid(child, &status, 0);
  ASSERT_TRUE(WIFEXITED(status)) << "killed by signal " << WTERMSIG(status);
  EXPECT_EQ(WEXITSTATUS(status), 0);
  for (const auto& e : std::filesystem::directory_iterator(dir.operator/("")))
    ADD_FAILURE() << "left behind: " << e.path();
}

TEST(HostileCli, AWriterKilledMidWriteLeavesNothingAfterTheNextWrite) {
  TempDir dir;
  const auto target = dir / "out.ply";
  // A big export, killed as soon as its temporary file appears.
  const SlowWriter w = start_slow_export(target);
  kill(w.pid, SIGKILL);
  int status = 0;
  waitpid(w.pid, &status, 0);
  ASSERT_TRUE(w.writing) << "the export never started writing";
  ASSERT_FALSE(std::filesystem::exists(target));
  std::size_t left = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir.operator/(""))) left += 1, (void)e;
  EXPECT_GE(left, 1u);  // SIGKILL cannot be caught: its temporary file is still there
  ASSERT_EQ(cli({"export", kAssets + "default.json", "-o", target.string(), "--density", "4"}).code,
            kExitOk);
  for (const auto& e : std::filesystem::directory_iterator(dir.operator/("")))
    EXPECT_EQ(e.path(), target) << "left behind";
}

TEST(HostileCli, DuplicateKeysAndSelfCrossingLoopsAreLocated) {
  TempDir dir;
  const auto dup = dir.file("dup.json", R"({"patchlab":1,"patches":[{"type":"bezier","type":"x",
      "degree":[1,1],"points":[[0,0,0],[1,0,0],[0,1,0],[1,1,1]]}]})");
  const CliResult d = cli({"analyze", dup.string()});
  EXPECT_EQ(d.code, kExitBadInput);
  EXPECT_EQ(d.err, "patchlab: " + dup.string() +
                       ": patches[0].type: duplicate key (a key may appear once in an object)\n");
  nlohmann::json net;
  for (int i = 0; i < 5; ++i)
    net["vertices"].push_back({std::cos(0.4 * M_PI * i), std::sin(0.4 * M_PI * i), 0.0});
  const int loop[5] = {0, 2, 4, 1, 3};
  for (int i = 0; i < 5; ++i) {
    const auto& a = net["vertices"][loop[i]];
    const auto& b = net["vertices"][loop[(i + 1) % 5]];
    nlohmann::json h1, h2;
    for (int c = 0; c < 3; ++c) {
      h1.push_back((2 * a[c].get<double>() + b[c].get<double>()) / 3);
      h2.push_back((a[c].get<double>() + 2 * b[c].get<double>()) / 3);
    }
    net["edges"].push_back({{"v", {loop[i], loop[(i + 1) % 5]}}, {"handles", {h1, h2}}});
  }
  net["faces"].push_back({{"loop", loop}});
  const auto star = dir.file("star.json", nlohmann::json{{"patchlab", 1}, {"network", net}}.dump());
  const CliResult s = cli({"analyze", star.string()});
  EXPECT_EQ(s.code, kExitBadInput);
  EXPECT_NE(s.err.find("network.faces[0].loop: the face's boundary crosses itself"),
            std::string::npos)
      << s.err;
}

TEST(HostileCli, AKeyWithANulIsPrintedWhole) {
  TempDir dir;
  const auto f = dir.file("nul.json", "{\"patchlab\": 1, \"before\\u0000after\": 1}");
  const Ran r = run_binary("analyze " + f.string());
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.output.find("before\\u0000after: unknown key"), std::string::npos) << r.output;
}

TEST(HostileCli, EveryShippedSceneExportsFiniteOutput) {
  TempDir dir;
  for (const auto& e : std::filesystem::recursive_directory_iterator(kAssets)) {
    if (e.path().extension() != ".json") continue;
    const auto out = dir / "a.obj";
    const CliResult r = cli({"export", e.path().string(), "-o", out.string()});
    ASSERT_EQ(r.code, kExitOk) << e.path() << r.err;
    const std::string obj = slurp(out);
    EXPECT_EQ(obj.find("nan"), std::string::npos) << e.path();
    EXPECT_EQ(obj.find("inf"), std::string::npos) << e.path();
    for (const Vec3& n : obj_normals(obj)) ASSERT_NEAR(glm::length(n), 1.0, 1e-12) << e.path();
  }
}

}  // namespace
}  // namespace pl::test
