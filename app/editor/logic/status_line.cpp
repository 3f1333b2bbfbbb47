#include "app/editor/logic/status_line.hpp"

#include <algorithm>
#include <vector>

namespace pl {

void StatusLine::say(std::string message, Clock::time_point now) {
  message_ = std::move(message);
  said_ = now;
}

std::string StatusLine::message(Clock::time_point now) const {
  if (message_.empty() || std::chrono::duration<double>(now - said_).count() >= kMessageSeconds)
    return "";
  return message_;
}

void StatusLine::add_frame(double ms) {
  frames_.push_back(ms);
  if (frames_.size() > kFrameHistory) frames_.pop_front();
}

double StatusLine::median_frame_ms() const {
  if (frames_.empty()) return 0;
  std::vector<double> sorted(frames_.begin(), frames_.end());
  std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
  return sorted[sorted.size() / 2];
}

}  // namespace pl
