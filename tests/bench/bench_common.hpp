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
  bool quick = false;  // tiny sizes: proves the program works (CI smoke test), figures meaningless
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

// One function per benchmark file; patchlab_bench.cpp calls them in order.
void bench_bezier(const Options& options);
void bench_gb(const Options& options);
void bench_gb_face(const Options& options);
void bench_engine(const Options& options);
void bench_catmull_clark(const Options& options);
void bench_cad(const Options& options);
void bench_curve(const Options& options);

}  // namespace pl::bench
