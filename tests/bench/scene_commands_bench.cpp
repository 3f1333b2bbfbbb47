// Whole-scene commands on a big network, as `patchlab` runs them (in process, through the
// command line's own entry point): analyze, OBJ export and a 1600x1200 render of the 1,536-face
// cube-sphere filled GB and filled Gregory, alternating, the median of three runs each; the GB
// over Gregory ratio of each command, and each command on every core over one core.
#include <oneapi/tbb/global_control.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <sstream>

#include "app/cli/cli.hpp"
#include "bench_common.hpp"
#include "core/io/scene_io.hpp"
#include "core/network/sample_networks.hpp"

namespace pl::bench {

namespace {

std::filesystem::path write_sphere(const std::filesystem::path& dir, int cells, FaceScheme scheme,
                                   const char* name) {
  Scene s;
  s.network = cube_sphere_network(cells, scheme);
  const auto file = dir / name;
  write_scene(file, s);
  return file;
}

void run(const std::vector<std::string>& args) {
  std::ostringstream out, err;
  if (run_cli(args, out, err) != 0) throw std::runtime_error("scene command failed: " + err.str());
}

}  // namespace

void bench_scene_commands(const Options& o) {
  const int cells = o.quick ? 2 : 16;  // 6 k^2 faces: 1,536
  const auto dir =
      std::filesystem::temp_directory_path() / ("patchlab-bench-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string gb = write_sphere(dir, cells, FaceScheme::GB, "gb.json").string();
  const std::string gregory =
      write_sphere(dir, cells, FaceScheme::Gregory, "gregory.json").string();
  const std::string obj = (dir / "out.obj").string(), png = (dir / "out.png").string();
  struct Command {
    const char* name;
    std::vector<std::string> (*args)(const std::string& file, const std::string& obj,
                                     const std::string& png);
  };
  const Command commands[] = {
      {"analyze",
       [](const std::string& f, const std::string&, const std::string&) {
         return std::vector<std::string>{"analyze", f};
       }},
      {"obj",
       [](const std::string& f, const std::string& obj, const std::string&) {
         return std::vector<std::string>{"export", f, "-o", obj};
       }},
      {"render",
       [](const std::string& f, const std::string&, const std::string& png) {
         return std::vector<std::string>{"render", f, "-o", png};
       }},
  };
  const int repeats = o.quick ? 1 : 3;
  for (const Command& c : commands) {
    std::vector<double> g, r;
    for (int i = 0; i < repeats; ++i) {  // alternating, so that a noisy moment hits both
      g.push_back(median_ms(1, [&] { run(c.args(gb, obj, png)); }));
      r.push_back(median_ms(1, [&] { run(c.args(gregory, obj, png)); }));
    }
    std::sort(g.begin(), g.end());
    std::sort(r.begin(), r.end());
    const double gb_ms = g[g.size() / 2], gregory_ms = r[r.size() / 2];
    const std::string n = c.name;
    figure(("scene_" + n + "_ms_gb_1536_faces").c_str(), gb_ms, "ms");
    figure(("scene_" + n + "_ms_gregory_1536_faces").c_str(), gregory_ms, "ms");
    figure(("scene_" + n + "_ratio_gb_over_gregory").c_str(), gb_ms / gregory_ms, "x");
    double one_ms = 0;
    {
      const oneapi::tbb::global_control one(oneapi::tbb::global_control::max_allowed_parallelism,
                                            1);
      one_ms = median_ms(repeats, [&] { run(c.args(gb, obj, png)); });
    }
    figure(("scene_" + n + "_speedup_all_cores_over_one_gb").c_str(), one_ms / gb_ms, "x");
  }
  std::filesystem::remove_all(dir);
}

}  // namespace pl::bench
