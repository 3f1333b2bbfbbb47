// Big free curves through the command line, in process: one cubic B-spline of N points and N
// cubic Bézier curves (a chain, so every end is a joint), N = 40,000 and 400,000, each through
// analyze, OBJ, PLY, render and convert. The scenes are written to a temporary directory.
// At the default density 32 the 400,000-point scenes are over the work bound (docs/limits.md), so
// the scaling figures (_400k over _40k) are taken at --density 8, where both sizes fit; the
// acceptance figures of the 40,000-point scenes are at the default density.
#include <unistd.h>

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

// Median wall time of the command, in ms; a failing command is reported and counts as 0.
double command_ms(int repeats, std::vector<std::string> args) {
  bool failed = false;
  const double ms = median_ms(repeats, [&] {
    std::ostringstream out, err;
    if (run_cli(args, out, err) != kExitOk && !failed) {
      failed = true;
      std::fprintf(stderr, "# curve_scale: %s failed: %s", args[0].c_str(), err.str().c_str());
    }
  });
  return failed ? 0.0 : ms;
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
    std::map<std::string, double> at_small;  // the density-8 figures of the small scene, by name
    for (const int n : {small, big}) {
      const std::string file =
          (dir / (std::string(kind.name) + std::to_string(n) + ".json")).string();
      std::ofstream(file) << kind.scene(n);
      const std::string tag = n == small ? tag_small : tag_big;
      // name, command line; density "" is the default.
      const std::vector<std::pair<const char*, std::vector<std::string>>> commands = {
          {"analyze", {"analyze", file}},
          {"obj", {"export", file, "-o", out + ".obj"}},
          {"ply", {"export", file, "-o", out + ".ply"}},
          {"render", {"render", file, "-o", out + ".png", "--size", "800x600"}},
          {"convert", {"convert", file, "-o", out + ".json"}},
      };
      for (const auto& [name, args] : commands) {
        // At density 8 (both sizes), and the 40,000-point scene at the default density too.
        std::vector<std::string> at8 = args;
        if (std::string(name) != "convert") at8.insert(at8.end(), {"--density", "8"});
        const std::string base = std::string("curve_") + name + "_ms_" + kind.name;
        const double ms = command_ms(n == big ? 1 : repeats, at8);
        figure((base + "_" + tag + "_d8").c_str(), ms, "ms");
        // The scaling target: 10 times the points in at most 10 times the time.
        if (n == small) at_small[name] = ms;
        if (n == big && at_small[name] > 0)
          figure((std::string("curve_") + name + "_ratio_" + kind.name + "_" + tag + "_over_" +
                  tag_small)
                     .c_str(),
                 ms / at_small[name], "x");
        if (n == small) figure((base + "_" + tag).c_str(), command_ms(repeats, args), "ms");
      }
      // The two figures the scaling target names: the B-spline through analyze, at density 8.
      if (std::string(kind.name) == "bspline") {
        const double ms = command_ms(n == big ? 1 : repeats, {"analyze", file, "--density", "8"});
        figure(("curve_analyze_ms_" + tag).c_str(), ms, "ms");
        if (n == small) at_small["named"] = ms;
        if (n == big && at_small["named"] > 0)
          figure(("curve_analyze_ratio_" + tag + "_over_" + tag_small).c_str(),
                 ms / at_small["named"], "x");
      }
      std::filesystem::remove(file);
    }
  }
  std::error_code ec;
  std::filesystem::remove_all(dir, ec);
}

}  // namespace pl::bench
