#include "core/mesh/polyline.hpp"

namespace pl {

CurvePolyline curve_polyline(const SceneCurve& curve, const std::string& name, int per_span) {
  CurvePolyline l;
  l.name = name;
  for (double t : curve_sample_parameters(curve, per_span))
    l.points.push_back(evaluate(curve, t).p);
  return l;
}

}  // namespace pl
