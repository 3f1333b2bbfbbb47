// The polylines the editor draws for the scene's free curves, kept up to date through edits:
// when only control points of a curve moved (a drag), the samples on the spans those points
// touch are recomputed (CurveSamples) and the rest of the curve is left alone, so a drag costs
// the same on a 10-point and a 1,000-point B-spline. Any other change of a curve (knots,
// weights, type, point count) re-samples that curve.
#pragma once

#include <optional>
#include <vector>

#include "core/eval/curve_samples.hpp"
#include "render/draw_scene.hpp"

namespace pl {

class FreeCurveLines {
 public:
  // Samples every curve again; `lines` gets one polyline per curve.
  void rebuild(const std::vector<SceneCurve>& curves, std::vector<Polyline>& lines);
  // Brings `lines` up to date with `curves`; false if the curves were added or removed (then
  // call rebuild).
  bool update(const std::vector<SceneCurve>& curves, std::vector<Polyline>& lines);
  // Samples recomputed by the last update (for tests and the drag figures).
  std::size_t last_update_samples() const { return last_update_samples_; }

 private:
  void resample(std::size_t c, const SceneCurve& curve, Polyline& line);

  std::vector<SceneCurve> drawn_;  // each curve as its polyline shows it
  // The incremental samples where the scene's points are the spline form's (Bézier, B-spline,
  // NURBS); empty for interpolating and Hermite curves, whose spline points are derived.
  std::vector<std::optional<CurveSamples>> samples_;
  std::size_t last_update_samples_ = 0;
};

}  // namespace pl
