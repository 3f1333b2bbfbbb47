#include "core/mesh/polyline.hpp"

namespace pl {

CurvePolyline curve_polyline(const SceneCurve& curve, const std::string& name, int per_span) {
  CurvePolyline l;
  l.name = name;
  const std::vector<double> ts = curve_sample_parameters(curve, per_span);
  l.points.reserve(ts.size());
  int span = -1;
  for (double t : ts) l.points.push_back(evaluate(curve, t, span).p);
  return l;
}

}  // namespace pl
