#include "app/cli/progress_line.hpp"

#include <unistd.h>

namespace pl {

namespace {

// Rewrites the line this often once it shows.
constexpr std::chrono::milliseconds kTick(200);
// The ProgressLine of the running sub-command (one at a time).
std::mutex active_mutex;
ProgressLine* active = nullptr;

}  // namespace

ProgressLine::ProgressLine(std::string title, std::FILE* out, bool terminal,
                           std::chrono::milliseconds delay)
    : title_(std::move(title)), out_(terminal ? out : nullptr), delay_(delay) {
  {
    std::lock_guard lock(active_mutex);
    if (!active) active = this;
  }
  if (out_) ticker_ = std::thread([this] { tick(); });
}

ProgressLine::ProgressLine(std::string title)
    : ProgressLine(std::move(title), stderr, isatty(fileno(stderr)) != 0) {}

ProgressLine::~ProgressLine() {
  {
    std::lock_guard lock(active_mutex);
    if (active == this) active = nullptr;
  }
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  if (ticker_.joinable()) ticker_.join();
  if (written_) {
    std::fputs("\r\033[K", out_);  // erased: what the command prints next starts clean
    std::fflush(out_);
  }
}

void ProgressLine::stage(std::string what) {
  std::lock_guard lock(mutex_);
  stage_ = std::move(what);
}

void ProgressLine::set_stage(std::string what) {
  std::lock_guard lock(active_mutex);
  if (active) active->stage(std::move(what));
}

void ProgressLine::tick() {
  const auto start = std::chrono::steady_clock::now();
  std::unique_lock lock(mutex_);
  if (wake_.wait_for(lock, delay_, [this] { return stop_; })) return;
  do {
    const double s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::fprintf(out_, "\r\033[K%s: %s (%.1f s)", title_.c_str(),
                 stage_.empty() ? "working" : stage_.c_str(), s);
    std::fflush(out_);
    written_ = true;
  } while (!wake_.wait_for(lock, kTick, [this] { return stop_; }));
}

}  // namespace pl
