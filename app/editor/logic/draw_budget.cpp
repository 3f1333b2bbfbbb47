#include "app/editor/logic/draw_budget.hpp"

#include <algorithm>
#include <cstdio>

namespace pl {

void DrawBudget::frame(double ms, bool moving) {
  if (!moving) {
    step_ = 0;
    count_ = 0;
    return;
  }
  recent_[count_++ % kWindow] = ms;
  if (count_ < kWindow) return;
  std::array<double, kWindow> sorted = recent_;
  std::nth_element(sorted.begin(), sorted.begin() + kWindow / 2, sorted.end());
  const double median = sorted[kWindow / 2];
  // Down a step over the budget; up a step when the larger scale would still fit it (the cost
  // is about proportional to the pixels, the square of the scale), with a margin against
  // going back and forth.
  const int last = int(kScales.size()) - 1;
  if (median > budget_ms_ && step_ < last) {
    ++step_;
    count_ = 0;
  } else if (step_ > 0) {
    const double up = kScales[step_ - 1] / kScales[step_];
    if (median * up * up < 0.8 * budget_ms_) {
      --step_;
      count_ = 0;
    }
  }
}

std::string DrawBudget::note() const {
  if (step_ == 0) return {};
  char b[64];
  std::snprintf(b, sizeof b, "view at %d %% while moving", int(kScales[step_] * 100 + 0.5));
  return b;
}

}  // namespace pl
