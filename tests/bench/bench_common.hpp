// Shared pieces of the benchmark program: options, timing, figure output.
// Every figure is printed as one line "figure NAME VALUE UNIT".
#pragma once

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <vector>

namespace pl::bench {

struct Options {
  bool quick = false;   // tiny sizes: proves the program works (CI smoke test), figures meaningless
  bool grains = false;  // --grains: the parallel grain sweep instead of the figures
};

inline void figure(const char* name, double value, const char* unit) {
  std::printf("figure %s %.6g %s\n", name, value, unit);
  std::fflush(stdout);
}

// Median wall time of `repeats` calls, in milliseconds.
inline double median_ms(int repeats, const std::function<void()>& f) {
  std::vector<double> t;
  for (int i = 0; i < repeats; ++i) {
    const auto a = std::chrono::steady_clock::now();
    f();
    const auto b = std::chrono::steady_clock::now();
    t.push_back(std::chrono::duration<double, std::milli>(b - a).count());
  }
  std::nth_element(t.begin(), t.begin() + t.size() / 2, t.end());
  return t[t.size() / 2];
}

// Median wall times of `repeats` calls of f with the machine as it is ("quiet") and with one core
// held busy by a spinning process (BusyCore), measured in `rounds` alternating rounds so both
// see the same background load.
struct QuietBusy {
  double quiet = 0, busy = 0;
  double ratio() const { return busy / quiet; }  // how much longer a call takes with a core busy
};
QuietBusy median_ms_quiet_busy(int repeats, int rounds, const std::function<void()>& f);

// Prints NAME (quiet), NAME_busy and RATIO_NAME, the busy figure over the quiet one (for a time,
// how many times longer; for a throughput, the fraction kept).
void figures_quiet_busy(const char* name, const char* unit, double quiet, double busy,
                        const char* ratio_name);

// One function per benchmark file; patchlab_bench.cpp calls them in order.
void bench_machine(const Options& options);
void bench_bezier(const Options& options);
void bench_gb(const Options& options);
void bench_gb_face(const Options& options);
void bench_interior(const Options& options);
void bench_engine(const Options& options);
void bench_catmull_clark(const Options& options);
void bench_cad(const Options& options);
void bench_cad_ngon(const Options& options);
void bench_curve(const Options& options);
void bench_curve_scale(const Options& options);
void bench_grains(const Options& options);
void bench_schemes(const Options& options);
void bench_scene_commands(const Options& options);

}  // namespace pl::bench
