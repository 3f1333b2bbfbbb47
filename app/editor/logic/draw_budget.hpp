// The editor's frame-time budget: while something moves (a drag, an orbit, a pan) the 3D view
// is drawn at a lower resolution when frames take longer than the budget, and at full resolution
// again at rest. A CPU rasteriser (Mesa's llvmpipe) pays per pixel: on a dense network a
// full-resolution frame costs three times its evaluation, so the scale is what holds the frame
// rate. The scale moves a step at a time, on the median of the last few frames, so one slow
// frame (an upload) does not make the view flicker between scales. GUI-free and unit-tested.
#pragma once

#include <array>
#include <string>

namespace pl {

class DrawBudget {
 public:
  // The scales the view is drawn at while moving, largest first.
  static constexpr std::array<double, 4> kScales{1.0, 0.75, 0.5, 0.35};
  static constexpr int kWindow = 5;  // frames whose median decides a step

  // `frame_ms`: the frame budget (33 ms: 30 frames a second).
  explicit DrawBudget(double frame_ms = 1000.0 / 30.0) : budget_ms_(frame_ms) {}

  // A frame took `ms` of work; `moving`: something was moving in it (at rest the view returns to
  // full resolution and the history is dropped).
  void frame(double ms, bool moving);
  // The resolution the next frame's 3D view is drawn at (1: full).
  double scale() const { return kScales[step_]; }
  // "view at 50 % while moving" while below full resolution; empty otherwise.
  std::string note() const;
  double budget_ms() const { return budget_ms_; }

 private:
  double budget_ms_;
  int step_ = 0;
  std::array<double, kWindow> recent_{};
  int count_ = 0;  // frames in recent_ since the last step
};

}  // namespace pl
