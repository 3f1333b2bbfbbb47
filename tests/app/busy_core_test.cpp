// The benchmarks' busy core: a process that really spins while the object lives, and is gone
// after.
#include "app/editor/logic/busy_core.hpp"

#include <gtest/gtest.h>
#include <signal.h>

#include <cerrno>
#include <chrono>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

namespace pl {
namespace {

// User plus system CPU time of process pid, in clock ticks (/proc/PID/stat fields 14 and 15).
long cpu_ticks(pid_t pid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/stat");
  std::string line;
  std::getline(in, line);
  std::istringstream rest(line.substr(line.rfind(')') + 2));  // after "pid (name) "
  std::string field;
  long utime = 0, stime = 0;
  for (int i = 3; i <= 15 && rest >> field; ++i) {
    if (i == 14) utime = std::stol(field);
    if (i == 15) stime = std::stol(field);
  }
  return utime + stime;
}

TEST(BusyCore, SpinsWhileAliveAndIsGoneAfter) {
  pid_t pid = -1;
  {
    const BusyCore busy;
    pid = busy.pid();
    ASSERT_GT(pid, 0);
    const long before = cpu_ticks(pid);
    const long ticks = sysconf(_SC_CLK_TCK);
    // Half a second of wall time: the spinner gets some of it even on a loaded machine.
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    EXPECT_GT(cpu_ticks(pid) - before, ticks / 20) << "the spinner used less than 50 ms of CPU";
  }
  EXPECT_EQ(kill(pid, 0), -1);
  EXPECT_EQ(errno, ESRCH);
}

}  // namespace
}  // namespace pl
