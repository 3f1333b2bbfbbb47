// Big free curves through the command line, in process: one cubic B-spline of N points and N
// cubic Bézier curves (a chain, so every end is a joint), N = 40,000 and 400,000, each through
// analyze, OBJ, PLY, render and convert. The scenes are written to a temporary directory.
// At the default density 32 the 400,000-point scenes are over the work bound (docs/limits.md), so
// the scaling figures (_400k over _40k) are taken at --density 8, where both sizes fit; the
// acceptance figures of the 40,000-point scenes are at the default density. Both sizes are
// measured the same way (medians of three samples, alternating, each run from a trimmed heap, a
// sample of the small scene the mean of ten runs in a row), so a ratio compares like with like.
#include <malloc.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "app/cli/cli.hpp"
#include "bench_common.hpp"

namespace pl::bench {

namespace {

std::string bspline_scene(int n) {
  nlohmann::json points = nlohmann::json::array();
  for (int i = 0; i < n; ++i)
    points.push_back({i * 0.01, std::sin(i * 0.05), 0.3 * std::cos(i * 0.031)});
  nlohmann::json curve = {{"type", "bspline"}, {"degree", 3}, {"points", points}};
  return nlohmann::json{{"patchlab", 1}, {"curves", {curve}}}.dump();
}

// A chain far from the origin (x up to N), as a digitised sketch in world coordinates.
std::string bezier_scene(int n) {
  nlohmann::json curves = nlohmann::json::array();
  for (int i = 0; i < n; ++i) {
    const double x = i;
    curves.push_back({{"type", "bezier"},
                      {"points",
                       {{x, 0, 0},
                        {x + 0.3, 0.5 * std::sin(i), 0},
                        {x + 0.7, -0.5 * std::cos(i), 0.1},
                        {x + 1, 0, 0}}}});
  }
  return nlohmann::json{{"patchlab", 1}, {"curves", curves}}.dump();
}

// One run of the command, in ms, from a trimmed heap: the memory freed by earlier runs is given
// back to the system first, so every run (of either size) allocates its memory afresh, as a
// command started from the shell does. Without it a small scene ran in memory kept warm by the
// runs before it while a big one, whose blocks glibc maps and unmaps, never did. A failing
// command is reported and counts as 0.
double command_ms(const std::vector<std::string>& args) {
  ::malloc_trim(0);
  std::ostringstream out, err;
  const auto a = std::chrono::steady_clock::now();
  const int code = run_cli(args, out, err);
  const auto b = std::chrono::steady_clock::now();
  if (code != kExitOk) {
    std::fprintf(stderr, "# curve_scale: %s failed: %s", args[0].c_str(), err.str().c_str());
    return 0.0;
  }
  return std::chrono::duration<double, std::milli>(b - a).count();
}

double median(std::vector<double> t) {
  std::nth_element(t.begin(), t.begin() + t.size() / 2, t.end());
  return t[t.size() / 2];
}

// The median times of the same command on the small and the big scene, their runs alternating so
// that both see the same background load. One sample of the small scene is the mean of `batch`
// runs in a row (the size ratio), so that both sizes are timed over stretches of about the same
// length: on this machine one run of a few hundred ms goes faster per point than the same work
// done for seconds (ten copies of the 40,000-point curve in one scene take as long as the one
// curve of 400,000 points, and 10% longer than ten times one copy alone), which a ratio of a
// short run over a long one would count against the algorithm.
std::pair<double, double> paired_ms(int repeats, int batch,
                                    const std::vector<std::string>& small_args,
                                    const std::vector<std::string>& big_args) {
  std::vector<double> small, big;
  for (int r = 0; r < repeats; ++r) {
    double sum = 0;
    for (int b = 0; b < batch; ++b) sum += command_ms(small_args);
    small.push_back(sum / batch);
    big.push_back(command_ms(big_args));
  }
  return {median(small), median(big)};
}

}  // namespace

void bench_curve_scale(const Options& options) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("patchlab-bench-curves-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const int small = options.quick ? 400 : 40000, big = 10 * small;
  const std::string tag_small = options.quick ? "quick" : "40k";
  const std::string tag_big = options.quick ? "quick10" : "400k";
  const int repeats = options.quick ? 1 : 3;
  struct Kind {
    const char* name;
    std::string (*scene)(int);
  };
  const std::string out = (dir / "out").string();
  for (const Kind& kind : {Kind{"bspline", bspline_scene}, Kind{"bezier", bezier_scene}}) {
    const auto file_of = [&](int n) {
      return (dir / (std::string(kind.name) + std::to_string(n) + ".json")).string();
    };
    for (const int n : {small, big}) std::ofstream(file_of(n)) << kind.scene(n);
    // name, command line for a scene file; density "" is the default.
    const auto command = [&](const std::string& name, const std::string& file) {
      const std::vector<std::pair<std::string, std::vector<std::string>>> all = {
          {"analyze", {"analyze", file}},
          {"obj", {"export", file, "-o", out + ".obj"}},
          {"ply", {"export", file, "-o", out + ".ply"}},
          {"render", {"render", file, "-o", out + ".png", "--size", "800x600"}},
          {"convert", {"convert", file, "-o", out + ".json"}},
      };
      for (const auto& [n, args] : all)
        if (n == name) return args;
      return std::vector<std::string>{};
    };
    const auto at8 = [](std::vector<std::string> args) {
      if (args[0] != "convert") args.insert(args.end(), {"--density", "8"});
      return args;
    };
    for (const std::string name : {"analyze", "obj", "ply", "render", "convert"}) {
      const std::string base = "curve_" + name + "_ms_" + kind.name;
      // The acceptance figure: the small scene at the default density.
      std::vector<double> t;
      for (int r = 0; r < repeats; ++r) t.push_back(command_ms(command(name, file_of(small))));
      figure((base + "_" + tag_small).c_str(), median(t), "ms");
      // The scaling target, at density 8: 10 times the points in at most 10 times the time.
      const auto [ms_small, ms_big] =
          paired_ms(repeats, big / small, at8(command(name, file_of(small))),
                    at8(command(name, file_of(big))));
      figure((base + "_" + tag_small + "_d8").c_str(), ms_small, "ms");
      figure((base + "_" + tag_big + "_d8").c_str(), ms_big, "ms");
      if (ms_small > 0)
        figure(("curve_" + name + "_ratio_" + kind.name + "_" + tag_big + "_over_" + tag_small)
                   .c_str(),
               ms_big / ms_small, "x");
    }
    // The two figures the scaling target names: the B-spline through analyze, at density 8.
    if (std::string(kind.name) == "bspline") {
      const auto [ms_small, ms_big] =
          paired_ms(repeats, big / small, at8(command("analyze", file_of(small))),
                    at8(command("analyze", file_of(big))));
      figure(("curve_analyze_ms_" + tag_small).c_str(), ms_small, "ms");
      figure(("curve_analyze_ms_" + tag_big).c_str(), ms_big, "ms");
      if (ms_small > 0)
        figure(("curve_analyze_ratio_" + tag_big + "_over_" + tag_small).c_str(), ms_big / ms_small,
               "x");
    }
    for (const int n : {small, big}) std::filesystem::remove(file_of(n));
  }
  std::error_code ec;
  std::filesystem::remove_all(dir, ec);
}

}  // namespace pl::bench
