// One contract across the sub-commands: what `analyze` refuses every export and `render` refuse
// with the same message before any writer runs; the STEP/IGES scale range; one exit status for
// wrong usage; file names printed escaped; temporaries removed on SIGTERM and SIGINT.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>

#include "cli_test_util.hpp"

namespace pl::test {
namespace {

const std::string kAssets = PATCHLAB_SOURCE_DIR "/assets/";

std::size_t entries(const std::filesystem::path& dir) {
  std::size_t n = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir)) n += 1, (void)e;
  return n;
}

// The longest run of decimal digits in s.
std::size_t longest_digit_run(const std::string& s) {
  std::size_t best = 0, run = 0;
  for (char c : s) {
    run = std::isdigit(static_cast<unsigned char>(c)) ? run + 1 : 0;
    best = std::max(best, run);
  }
  return best;
}

const std::vector<std::string> kExports = {"obj", "ply", "off", "stl", "step", "igs"};

// analyze's refusal, then the same refusal, word for word, from every export and from render,
// with nothing written.
void expect_one_refusal(const TempDir& dir, const std::filesystem::path& scene,
                        const std::string& expected_part) {
  const CliResult a = cli({"analyze", scene.string()});
  ASSERT_EQ(a.code, kExitBadInput) << a.out;
  EXPECT_NE(a.err.find(expected_part), std::string::npos) << a.err;
  for (const std::string& ext : kExports) {
    const auto out = dir / ("out." + ext);
    const CliResult r = cli({"export", scene.string(), "-o", out.string()});
    EXPECT_EQ(r.code, kExitBadInput) << ext << ": " << r.out;
    EXPECT_EQ(r.err, a.err) << ext;
    EXPECT_FALSE(std::filesystem::exists(out)) << ext;
  }
  const auto png = dir / "out.png";
  const CliResult r = cli({"render", scene.string(), "-o", png.string()});
  EXPECT_EQ(r.code, kExitBadInput);
  EXPECT_EQ(r.err, a.err);
  EXPECT_FALSE(std::filesystem::exists(png));
}

TEST(CliContract, WhatAnalyzeRefusesForANonFiniteSurfaceEveryExportRefuses) {
  // The G2 pair join squares lengths: at scale 1e150 its construction overflows. STEP and IGES
  // wrote such scenes with exit 0.
  TempDir dir;
  const auto f = dir.file(
      "pj.json",
      scaled(nlohmann::json::parse(slurp(kAssets + "classic/pair-join.json")), 1e150).dump());
  expect_one_refusal(dir, f, "patch \"g2-pair\" at (u, v) = (");
}

TEST(CliContract, WhatAnalyzeRefusesForANonFiniteCurveEveryExportRefuses) {
  // Numbers in range whose products overflow: a weight of 1e300 on a coordinate of 1e150.
  TempDir dir;
  const auto f = dir.file("w.json", R"({"patchlab": 1, "curves": [{"type": "nurbs", "degree": 2,
      "points": [[0, 0, 0], [1e150, 1e150, 0], [2, 0, 0]], "weights": [1, 1e300, 1]}]})");
  expect_one_refusal(dir, f, "curves[0]: the curve is not finite");
}

TEST(CliContract, CadExportStatesItsScaleRangeInShortNumbers) {
  TempDir dir;
  const auto scene = nlohmann::json::parse(slurp(kAssets + "default.json"));
  for (double s : {1e76, 1e120, 1e150, 1e-30, 1e-150}) {
    const auto f = dir.file("s.json", scaled(scene, s).dump());
    // Every other command accepts the scene at this scale.
    ASSERT_EQ(cli({"analyze", f.string()}).code, kExitOk) << s;
    for (const std::string ext : {"step", "igs"}) {
      const auto out = dir / ("s." + ext);
      const CliResult r = cli({"export", f.string(), "-o", out.string()});
      EXPECT_EQ(r.code, kExitBadInput) << s << " " << ext;
      EXPECT_NE(r.err.find("is outside the range STEP and IGES export supports"), std::string::npos)
          << r.err;
      // After the file's name (its temporary directory has digits): a 100-digit number before.
      EXPECT_LE(longest_digit_run(r.err.substr(r.err.find("s.json"))), 4u) << r.err;
      EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
      EXPECT_FALSE(std::filesystem::exists(out));
    }
  }
}

TEST(CliContract, AnUnknownExtensionIsWrongUsageInEveryCommand) {
  TempDir dir;
  const std::string scene = kAssets + "default.json";
  const auto out = dir / "out.xyz";
  // export exited 1 here, render and convert 2.
  EXPECT_EQ(cli({"export", scene, "-o", out.string()}).code, kExitUsage);
  EXPECT_EQ(cli({"render", scene, "-o", out.string()}).code, kExitUsage);
  EXPECT_EQ(cli({"convert", scene, "-o", out.string()}).code, kExitUsage);
  EXPECT_EQ(cli({"sample", "cube-sphere", "-o", out.string()}).code, kExitUsage);
  // The input's extension too, before the file is opened (gbnet already did so).
  const auto in = dir.file("scene.txt", "{}");
  for (const std::string cmd : {"analyze", "export", "render", "convert", "gbnet"}) {
    std::vector<std::string> args{cmd, in.string()};
    if (cmd != "analyze") args.insert(args.end(), {"-o", (dir / "o.obj").string()});
    if (cmd == "render") args.back() = (dir / "o.png").string();
    if (cmd == "convert") args.back() = (dir / "o.json").string();
    if (cmd == "gbnet")
      args.back() = (dir / "o.gbp").string(), args.push_back("--elevate"), args.push_back("1");
    EXPECT_EQ(cli(args).code, kExitUsage) << cmd;
  }
  EXPECT_EQ(entries(dir / ""), 1u);  // nothing written
}

TEST(CliContract, AnUnknownViewIsWrongUsageAndAMissingCameraFileBadInput) {
  TempDir dir;
  const std::string scene = kAssets + "default.json";
  const auto png = dir / "v.png";
  const CliResult r = cli({"render", scene, "-o", png.string(), "--view", "sideways"});
  EXPECT_EQ(r.code, kExitUsage);  // 1, "cannot open", before
  EXPECT_NE(r.err.find("--view takes iso, front"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("cannot open"), std::string::npos) << r.err;
  const CliResult m = cli({"render", scene, "-o", png.string(), "--view", (dir / "cam.json")});
  EXPECT_EQ(m.code, kExitBadInput);
  EXPECT_NE(m.err.find("cannot open"), std::string::npos) << m.err;
  EXPECT_FALSE(std::filesystem::exists(png));
}

TEST(CliContract, FileNamesArePrintedEscapedOnOneLine) {
  TempDir dir;
  const auto bad = dir.file("two\nlines.json", "{\"patchlab\": 1, \"patches\": 7}");
  for (const std::string cmd : {"analyze", "export", "convert"}) {
    std::vector<std::string> args{cmd, bad.string()};
    if (cmd == "export") args.insert(args.end(), {"-o", (dir / "o.obj").string()});
    if (cmd == "convert") args.insert(args.end(), {"-o", (dir / "o.json").string()});
    const CliResult r = cli(args);
    EXPECT_EQ(r.code, kExitBadInput) << cmd;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << cmd << ": " << r.err;
    EXPECT_NE(r.err.find("two\\u000alines.json: patches: expected an array"), std::string::npos)
        << r.err;
  }
  // An output name, in a write error and in what the command says it wrote.
  const std::string target = (dir / "no such\ndir" / "o.obj").string();
  const CliResult w = cli({"export", kAssets + "default.json", "-o", target, "--density", "2"});
  EXPECT_EQ(w.code, kExitBadInput);
  EXPECT_EQ(std::count(w.err.begin(), w.err.end(), '\n'), 1) << w.err;
  EXPECT_NE(w.err.find("no such\\u000adir"), std::string::npos) << w.err;
  const CliResult ok = cli(
      {"export", kAssets + "default.json", "-o", (dir / "a\nb.obj").string(), "--density", "2"});
  EXPECT_EQ(ok.code, kExitOk) << ok.err;
  EXPECT_EQ(std::count(ok.out.begin(), ok.out.end(), '\n'), 1) << ok.out;
  EXPECT_NE(ok.out.find("a\\u000ab.obj"), std::string::npos) << ok.out;
}

// The binary exporting a big PLY, stopped by `sig` as soon as its temporary file appears: it
// dies of the signal and leaves nothing behind (the next write was needed after SIGKILL only).
void expect_stop_leaves_nothing(int sig) {
  TempDir dir;
  const auto target = dir / "out.ply";
  const SlowWriter w = start_slow_export(target, sig);
  kill(w.pid, sig);
  int status = 0;
  waitpid(w.pid, &status, 0);
  ASSERT_TRUE(w.writing) << "the export never started writing";
  ASSERT_FALSE(std::filesystem::exists(target)) << "the export finished before the signal";
  ASSERT_TRUE(WIFSIGNALED(status)) << "exit status " << WEXITSTATUS(status);
  EXPECT_EQ(WTERMSIG(status), sig);
  for (const auto& e : std::filesystem::directory_iterator(dir / ""))
    ADD_FAILURE() << "left behind: " << e.path();
}

TEST(CliContract, SigtermRemovesTheTemporaryFile) {
  expect_stop_leaves_nothing(SIGTERM);
}

TEST(CliContract, SigintRemovesTheTemporaryFile) {
  expect_stop_leaves_nothing(SIGINT);
}

}  // namespace
}  // namespace pl::test
