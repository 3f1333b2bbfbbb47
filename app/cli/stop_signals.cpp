#include "app/cli/stop_signals.hpp"

#include <signal.h>

#include <mutex>

#include "core/io/atomic_file.hpp"

namespace pl {

namespace {

void on_stop_signal(int sig) {
  remove_temporaries_in_flight();
  // SA_RESETHAND restored the default action and SA_NODEFER left the signal unblocked: raising
  // it again ends the process as the signal would have.
  ::raise(sig);
}

}  // namespace

void remove_temporaries_on_stop_signals() {
  static std::once_flag once;
  std::call_once(once, [] {
    for (int sig : {SIGTERM, SIGINT, SIGHUP}) {
      struct sigaction old {};
      // A signal the caller chose to ignore (nohup, a shell's background job) stays ignored.
      if (::sigaction(sig, nullptr, &old) == 0 && old.sa_handler == SIG_IGN) continue;
      struct sigaction sa {};
      sa.sa_handler = on_stop_signal;
      sigemptyset(&sa.sa_mask);
      sa.sa_flags = SA_RESETHAND | SA_NODEFER;
      ::sigaction(sig, &sa, nullptr);
    }
  });
}

}  // namespace pl
