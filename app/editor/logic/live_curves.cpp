#include "app/editor/logic/live_curves.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "render/draw_scene_builder.hpp"
#include "app/editor/logic/curve_edits.hpp"

namespace pl {

LiveCurves::LiveCurves(bool combs, int teeth) : combs_(combs), teeth_(teeth) {
  if (teeth < 1)
    throw std::invalid_argument("LiveCurves: teeth must be at least 1, got " +
                                std::to_string(teeth));
}

void LiveCurves::configure(bool combs, int teeth) {
  if (teeth < 1)
    throw std::invalid_argument("LiveCurves: teeth must be at least 1, got " +
                                std::to_string(teeth));
  if (combs == combs_ && (!combs || teeth == teeth_)) {
    teeth_ = teeth;  // without combs the count changes nothing computed
    return;
  }
  combs_ = combs;
  teeth_ = teeth;
  stale_ = true;
}

namespace {

// A network face's sides as its edges' polylines, per domain side; empty when the topology does
// not describe the face.
std::vector<CurvatureComb> face_edge_borders(const Network& net, const NetworkTopology& topology,
                                             const SceneSurface& s) {
  if (s.face < 0 || s.face >= int(topology.face_sides.size())) return {};
  const auto& sides = topology.face_sides[s.face];
  const int n = s.evaluator->patch().domain().side_count();
  if (sides.size() != s.patch_side.size() || int(sides.size()) != n) return {};
  std::vector<CurvatureComb> borders(n);
  for (std::size_t i = 0; i < sides.size(); ++i) {
    const int d = s.patch_side[i], e = sides[i].edge;
    if (d < 0 || d >= n || e < 0 || e >= int(net.edges.size()) || !borders[d].points.empty())
      return {};
    borders[d].points = edge_polyline(net, e);
    if (sides[i].reversed) std::reverse(borders[d].points.begin(), borders[d].points.end());
  }
  return borders;
}

}  // namespace

bool LiveCurves::follow(const Scene& scene, const SceneSurfaces& surfaces, uint64_t from,
                        uint64_t to, const std::vector<int>& changed,
                        const NetworkTopology* topology) {
  const std::size_t n = surfaces.surfaces.size();
  const int teeth = combs_ ? teeth_ : 0;
  auto surface_borders = [&](const SceneSurface& s) {
    if (teeth == 0 && topology && scene.network && s.face >= 0) {
      std::vector<CurvatureComb> b = face_edge_borders(*scene.network, *topology, s);
      if (!b.empty()) return b;
    }
    return pl::surface_borders(s, teeth);
  };
  if (!stale_ && revision_ == to) return false;  // e.g. the fine view catching up after a drag
  last_free_resampled_ = last_free_spans_resampled_ = 0;
  if (stale_) combed_curves_.clear();
  follow_free_curves(scene.curves);
  if (stale_ || revision_ != from || borders_.size() != n) {
    borders_.clear();
    on_network_.clear();
    for (const SceneSurface& s : surfaces.surfaces) {
      borders_.push_back(surface_borders(s));
      on_network_.push_back(s.face >= 0);
    }
  } else {
    for (int i : changed) borders_.at(i) = surface_borders(surfaces.surfaces[i]);
  }
  // Network combs: a few hundred Bezier evaluations, recomputed whole.
  network_combs_.clear();
  if (combs_ && scene.network) network_combs_ = pl::network_combs(*scene.network, teeth_);
  stale_ = false;
  revision_ = to;
  ++serial_;
  return true;
}

bool LiveCurves::follow_free_curves(const std::vector<SceneCurve>& curves) {
  if (!combs_) {
    const bool had = !free_combs_.empty();
    free_combs_.clear();
    combed_curves_.clear();
    return had;
  }
  // By index: an inserted or removed curve resamples the curves after it (a rare edit).
  if (combed_curves_.size() != curves.size()) {
    combed_curves_.resize(curves.size());
    free_combs_.resize(curves.size());
    for (std::size_t c = 0; c < curves.size(); ++c) combed_curves_[c].points.clear();
  }
  bool changed = false;
  for (std::size_t c = 0; c < curves.size(); ++c) {
    const SceneCurve& curve = curves[c];
    SceneCurve& combed = combed_curves_[c];
    if (!combed.points.empty() && same_but_points(combed, curve)) {
      // Only points moved: the combs of the spans they touch (p + 1 of a spline's), not the
      // curve's (a drag on a 1,000-point B-spline resamples 4 spans, not 997).
      const auto range = moved_range(combed, curve);
      if (!range) continue;
      combed.points = curve.points;
      const auto spans = curve_spans(curve);
      for (std::size_t k = 0; k < spans.size() && k < free_combs_[c].size(); ++k)
        if (spans[k].first < range->second && spans[k].second > range->first) {
          free_combs_[c][k] = free_curve_span_comb(curve, spans[k], teeth_);
          ++last_free_spans_resampled_;
        }
      ++last_free_resampled_;
      changed = true;
      continue;
    }
    combed = curve;
    free_combs_[c] = pl::free_curve_combs(curve, teeth_);
    last_free_spans_resampled_ += free_combs_[c].size();
    ++last_free_resampled_;
    changed = true;
  }
  return changed;
}

std::vector<const CurvatureComb*> LiveCurves::free_comb_refs() const {
  std::vector<const CurvatureComb*> refs;
  for (const auto& curve : free_combs_)
    for (const CurvatureComb& c : curve) refs.push_back(&c);
  return refs;
}

std::vector<const CurvatureComb*> LiveCurves::network_comb_refs() const {
  std::vector<const CurvatureComb*> refs;
  for (const CurvatureComb& c : network_combs_) refs.push_back(&c);
  return refs;
}

std::vector<const CurvatureComb*> LiveCurves::border_refs() const {
  std::vector<const CurvatureComb*> refs;
  for (const auto& surface : borders_)
    for (const CurvatureComb& c : surface) refs.push_back(&c);
  return refs;
}

std::vector<bool> LiveCurves::border_on_network() const {
  std::vector<bool> flags;
  for (std::size_t s = 0; s < borders_.size(); ++s)
    flags.insert(flags.end(), borders_[s].size(), on_network_[s]);
  return flags;
}

}  // namespace pl
