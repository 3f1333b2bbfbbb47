// The status bar's figures and message: frame times (the median of the last frames' work, not
// the idle wait), the last evaluation and settle times, and one message that fades after a few
// seconds. GUI-free and unit-tested; the bar only prints them.
#pragma once

#include <chrono>
#include <deque>
#include <string>

namespace pl {

class StatusLine {
 public:
  using Clock = std::chrono::steady_clock;
  static constexpr double kMessageSeconds = 8.0;
  static constexpr std::size_t kFrameHistory = 120;

  void say(std::string message, Clock::time_point now = Clock::now());
  // The message while it is fresh, else empty.
  std::string message(Clock::time_point now = Clock::now()) const;

  void add_frame(double ms);
  double median_frame_ms() const;

  // A document replaced the shown one (New, Open, a drop, a recovery): the figures measured on
  // the one before say nothing about it; they read 0 until measured again.
  void clear_figures() { eval_ms = settle_ms = 0; }

  double eval_ms = 0;    // last evaluation: a document's first, or a re-evaluation after an edit
  double settle_ms = 0;  // last release to fine surfaces shown

 private:
  std::string message_;
  Clock::time_point said_;
  std::deque<double> frames_;
};

}  // namespace pl
