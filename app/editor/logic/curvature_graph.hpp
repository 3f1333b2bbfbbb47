// The curvature graph of a free curve (κ against t, as the curvature graphs of CAD tools draw
// it): the samples per span of the drawn curve, so a knot is a sample and a jump of curvature
// at a knot shows as a step. GUI-free (the window that plots it is curvature_graph_window.cpp).
#pragma once

#include <vector>

#include "core/curve/scene_curve.hpp"

namespace pl {

struct CurvatureGraph {
  std::vector<double> t, kappa;  // increasing t; kappa finite (0 where the speed vanishes)
  double kappa_min = 0, kappa_max = 0;
  std::vector<double> knots;  // the interior span ends, for tick marks
};

CurvatureGraph curvature_graph(const SceneCurve& curve, int per_span);

}  // namespace pl
