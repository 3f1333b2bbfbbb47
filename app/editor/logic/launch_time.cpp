#include "app/editor/logic/launch_time.hpp"

#include <unistd.h>

#include <chrono>
#include <fstream>
#include <sstream>
#include <string>

namespace pl {

namespace {

const auto kLoaded = std::chrono::steady_clock::now();

// The process's start in seconds after boot: field 22 of /proc/self/stat, in clock ticks. The
// second field (the command name) may hold spaces, so fields are counted after its ')'.
double start_seconds_after_boot() {
  std::ifstream in("/proc/self/stat");
  std::string stat((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto close = stat.rfind(')');
  if (close == std::string::npos) return -1;
  std::istringstream fields(stat.substr(close + 1));
  std::string field;
  for (int i = 3; i <= 22 && fields >> field; ++i)
    if (i == 22) {
      const long ticks = sysconf(_SC_CLK_TCK);
      return ticks > 0 ? std::stod(field) / double(ticks) : -1;
    }
  return -1;
}

}  // namespace

double ms_since_launch() {
  try {
    double uptime = -1;
    std::ifstream("/proc/uptime") >> uptime;
    const double start = start_seconds_after_boot();
    if (uptime >= 0 && start >= 0 && uptime >= start) return (uptime - start) * 1000.0;
  } catch (const std::exception&) {
  }
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - kLoaded)
      .count();
}

}  // namespace pl
