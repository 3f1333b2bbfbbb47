// Quiet and busy-core timings in the same run (bench_common.hpp).
#include <string>

#include "app/editor/logic/busy_core.hpp"
#include "bench_common.hpp"

namespace pl::bench {

namespace {
double median(std::vector<double> t) {
  std::nth_element(t.begin(), t.begin() + t.size() / 2, t.end());
  return t[t.size() / 2];
}

void time_calls(int calls, const std::function<void()>& f, std::vector<double>& out) {
  for (int i = 0; i < calls; ++i) {
    const auto a = std::chrono::steady_clock::now();
    f();
    const auto b = std::chrono::steady_clock::now();
    out.push_back(std::chrono::duration<double, std::milli>(b - a).count());
  }
}
}  // namespace

QuietBusy median_ms_quiet_busy(int repeats, int rounds, const std::function<void()>& f) {
  rounds = std::max(1, std::min(rounds, repeats));
  std::vector<double> quiet, busy;
  for (int r = 0; r < rounds; ++r) {
    const int calls = (repeats * (r + 1)) / rounds - (repeats * r) / rounds;
    time_calls(calls, f, quiet);
    const BusyCore spinner;
    f();  // the first call with the spinner running is not timed: a warm-up, like the quiet ones'
    time_calls(calls, f, busy);
  }
  return {median(quiet), median(busy)};
}

void figures_quiet_busy(const char* name, const char* unit, double quiet, double busy,
                        const char* ratio_name) {
  figure(name, quiet, unit);
  figure((std::string(name) + "_busy").c_str(), busy, unit);
  figure(ratio_name, busy / quiet, "x");
}

}  // namespace pl::bench
