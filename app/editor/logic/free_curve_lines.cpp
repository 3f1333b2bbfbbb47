#include "app/editor/logic/free_curve_lines.hpp"

#include <algorithm>

#include "render/draw_scene_builder.hpp"

namespace pl {

namespace {

bool same_shape(const SceneCurve& a, const SceneCurve& b) {
  return a.type == b.type && a.degree == b.degree && a.knots == b.knots && a.weights == b.weights &&
         a.tangents == b.tangents && a.points.size() == b.points.size();
}

bool points_are_spline_points(const SceneCurve& c) {
  return c.type == CurveType::Bezier || c.type == CurveType::BSpline || c.type == CurveType::Nurbs;
}

}  // namespace

void FreeCurveLines::resample(std::size_t c, const SceneCurve& curve, Polyline& line) {
  drawn_[c] = curve;
  samples_[c].reset();
  line.clear();
  const int per_span = free_curve_samples_per_span(curve);
  if (points_are_spline_points(curve)) {
    samples_[c].emplace(curve, per_span);
    for (const CurvePoint& s : samples_[c]->samples()) line.push_back(s.p);
  } else {
    for (double t : curve_sample_parameters(curve, per_span)) line.push_back(evaluate(curve, t).p);
  }
  last_update_samples_ += line.size();
}

void FreeCurveLines::rebuild(const std::vector<SceneCurve>& curves, std::vector<Polyline>& lines) {
  drawn_.assign(curves.size(), SceneCurve{});
  samples_.clear();
  samples_.resize(curves.size());
  lines.assign(curves.size(), Polyline{});
  last_update_samples_ = 0;
  for (std::size_t c = 0; c < curves.size(); ++c) resample(c, curves[c], lines[c]);
}

bool FreeCurveLines::update(const std::vector<SceneCurve>& curves, std::vector<Polyline>& lines) {
  if (curves.size() != drawn_.size() || lines.size() != curves.size()) return false;
  last_update_samples_ = 0;
  for (std::size_t c = 0; c < curves.size(); ++c) {
    const SceneCurve& curve = curves[c];
    SceneCurve& drawn = drawn_[c];
    if (!same_shape(curve, drawn) || !samples_[c]) {
      if (curve.points != drawn.points || !same_shape(curve, drawn)) resample(c, curve, lines[c]);
      continue;
    }
    drawn.name = curve.name;
    for (std::size_t i = 0; i < curve.points.size(); ++i) {
      if (curve.points[i] == drawn.points[i]) continue;
      drawn.points[i] = curve.points[i];
      const auto [first, last] = samples_[c]->move_point(i, curve.points[i]);
      for (std::size_t k = first; k < last; ++k) lines[c][k] = samples_[c]->samples()[k].p;
      last_update_samples_ += last - first;
    }
  }
  return true;
}

}  // namespace pl
