// A core held busy by another process, for the benchmarks that measure how the editor and the
// core cope when the machine is not theirs alone (a build, a browser, the rasteriser of another
// window): a child process spins at this process's priority for as long as the object lives.
// The child is not pinned: the kernel schedules it like any other busy process.
#pragma once

#include <sys/types.h>

namespace pl {

class BusyCore {
 public:
  // Starts the spinning process (a shell loop); throws std::runtime_error if it cannot. The
  // loop also ends when the thread that made this object ends, so a crash leaves no spinner.
  BusyCore();
  // Kills the spinner and waits for it.
  ~BusyCore();
  BusyCore(const BusyCore&) = delete;
  BusyCore& operator=(const BusyCore&) = delete;

  pid_t pid() const { return pid_; }

 private:
  pid_t pid_ = -1;
};

}  // namespace pl
