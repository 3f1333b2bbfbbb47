#include "core/mesh/polyline.hpp"

namespace pl {

CurvePolyline curve_polyline(const SceneCurve& curve, const std::string& name, int per_span) {
  CurvePolyline l;
  l.name = name;
  l.points.reserve(curve_span_count(curve) * per_span + 1);
  int span = -1;
  for_each_sample_parameter(curve, per_span,
                            [&](double t) { l.points.push_back(evaluate(curve, t, span).p); });
  return l;
}

}  // namespace pl
