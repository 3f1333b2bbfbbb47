// A progress line for command-line work that takes a while: once the work has run for `delay`,
// "patchlab export: evaluating 1536 surfaces (2.4 s)" is written on one line, rewritten in place
// a few times a second and erased when the work ends. Only on a terminal: a pipe or a log gets
// nothing, so scripts and logs stay clean.
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <mutex>
#include <string>
#include <thread>

namespace pl {

class ProgressLine {
 public:
  // Writes to `out` only when `terminal`; `title` starts the line ("patchlab export").
  ProgressLine(std::string title, std::FILE* out, bool terminal,
               std::chrono::milliseconds delay = std::chrono::milliseconds(1000));
  // The line for stderr, when stderr is a terminal.
  explicit ProgressLine(std::string title);
  ~ProgressLine();  // stops the ticker and erases the line if it was written
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  // What is being done now: shown from the next tick.
  void stage(std::string what);
  // The ProgressLine alive on this process (the sub-command's), or none: commands name their
  // stages through it without being handed one.
  static void set_stage(std::string what);

 private:
  void tick();
  std::string title_, stage_;
  std::FILE* out_;
  std::chrono::milliseconds delay_;
  bool written_ = false, stop_ = false;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::thread ticker_;
};

}  // namespace pl
