// Whole-scene commands on a big network, as `patchlab` runs them (in process, through the
// command line's own entry point): analyze, OBJ export and a 1600x1200 render of the 1,536-face
// cube-sphere filled GB and filled Gregory, alternating, the median of three runs each; the GB
// over Gregory ratio of each command (in process), and each GB command run as the patchlab
// program bound to one core against the program on every core (its speed-up).
#include <fcntl.h>
#include <sched.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
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

// The patchlab program run with `args` on the first `cpus` processors this process may use (all
// of them for 0): every thread it starts, the renderer's (Mesa's llvmpipe) included, is bound to
// them, as `taskset` would. Its wall time in ms.
double run_program_ms(const std::vector<std::string>& args, int cpus) {
  cpu_set_t mine;
  CPU_ZERO(&mine);
  sched_getaffinity(0, sizeof mine, &mine);
  cpu_set_t use;
  CPU_ZERO(&use);
  for (int c = 0, taken = 0; c < CPU_SETSIZE && (cpus == 0 || taken < cpus); ++c)
    if (CPU_ISSET(c, &mine)) CPU_SET(c, &use), ++taken;
  std::vector<std::string> argv_strings{PATCHLAB_CLI_PATH};
  argv_strings.insert(argv_strings.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : argv_strings) argv.push_back(a.data());
  argv.push_back(nullptr);
  const auto start = std::chrono::steady_clock::now();
  const pid_t child = fork();
  if (child == 0) {
    sched_setaffinity(0, sizeof use, &use);
    const int null = open("/dev/null", O_WRONLY);
    dup2(null, 1), dup2(null, 2);
    execv(argv[0], argv.data());
    _exit(127);
  }
  int status = 0;
  if (child < 0 || waitpid(child, &status, 0) != child || !WIFEXITED(status) ||
      WEXITSTATUS(status) != 0)
    throw std::runtime_error("scene command failed: " + argv_strings[0] + " " + args.at(0));
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
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
    // The program pinned to one core against the program on every core, alternating.
    std::vector<double> one, all;
    for (int i = 0; i < repeats; ++i) {
      one.push_back(run_program_ms(c.args(gb, obj, png), 1));
      all.push_back(run_program_ms(c.args(gb, obj, png), 0));
    }
    std::sort(one.begin(), one.end());
    std::sort(all.begin(), all.end());
    figure(("scene_" + n + "_speedup_all_cores_over_one_gb").c_str(),
           one[one.size() / 2] / all[all.size() / 2], "x");
  }
  std::filesystem::remove_all(dir);
}

}  // namespace pl::bench
