#include "app/editor/logic/busy_core.hpp"

#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <stdexcept>
#include <string>
#include <thread>

namespace pl {

// A shell loop, not a forked copy of this process spinning: after fork() every page this process
// writes first would be copied (copy on write) for as long as the child lives, and that would be
// measured as the cost of the busy core. vfork shares the address space until the exec, so
// nothing is copied. The loop runs in a session of its own, like a build or a browser: with the
// kernel's autogroup scheduling a spinner in this process's session would take its time from
// this process's share instead of from the machine's. The kernel kills the loop when the thread
// that started it ends (prctl), so a crash leaves no spinner behind.
BusyCore::BusyCore() {
  const pid_t parent = getpid();
  pid_ = vfork();
  if (pid_ == 0) {  // until the exec only system calls: this is the parent's memory
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (getppid() != parent) _exit(0);
    setsid();
    execl("/bin/sh", "sh", "-c", "while :; do :; done", static_cast<char*>(nullptr));
    _exit(127);
  }
  if (pid_ < 0)
    throw std::runtime_error(std::string("cannot start a spinning process: ") +
                             std::strerror(errno));
  int status = 0;
  if (waitpid(pid_, &status, WNOHANG) == pid_) {
    pid_ = -1;
    throw std::runtime_error("cannot start a spinning process: /bin/sh did not run");
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
