// A named polyline: a free curve sampled for export (OBJ `l` lines).
#pragma once

#include <string>
#include <vector>

#include "core/curve/scene_curve.hpp"

namespace pl {

struct CurvePolyline {
  std::string name;
  std::vector<Vec3> points;
};

// The curve's points at per_span + 1 uniform parameters in each span, span after span, the point
// two spans share written once (curve_sample_parameters).
CurvePolyline curve_polyline(const SceneCurve& curve, const std::string& name, int per_span);

}  // namespace pl
