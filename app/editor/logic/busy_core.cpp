#include "app/editor/logic/busy_core.hpp"

#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>
#include <thread>

namespace pl {

BusyCore::BusyCore() {
  const pid_t parent = getpid();
  pid_ = fork();
  if (pid_ < 0)
    throw std::runtime_error(std::string("cannot start a spinning process: ") +
                             std::strerror(errno));
  if (pid_ == 0) {
    // The child of a threaded process may only make async-signal-safe calls: two system calls,
    // then arithmetic until the parent kills it (or dies itself).
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (getppid() != parent) _exit(0);
    volatile unsigned long spin = 0;
    for (;;) spin = spin + 1;
  }
  // Let the spinner reach the run queue before anything is measured.
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
}

BusyCore::~BusyCore() {
  if (pid_ <= 0) return;
  kill(pid_, SIGKILL);
  int status = 0;
  while (waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
  }
}

}  // namespace pl
