// The Continuity panel's figures: analyze_scene of the fine (at rest) surfaces of each filling
// shown (the scene's own, or the comparison's Gregory and GB fillings), per shared edge the G0
// gap, the G1 normal angle and the mean-curvature jump, and the vertices whose edge end tangents
// had to be projected into their tangent plane. An edge is a warning only when its angle exceeds
// the threshold the user sets (Preferences::continuity_threshold_deg, 0.1 degrees by default):
// rounding leaves angles of 1e-6 degrees on exact G1 joins, which are no news to a designer.
// Recomputed once per document revision and layout, only from settled surfaces: analysing
// every drag step would cost more than the drag itself. GUI-free and unit-tested.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "core/analysis/scene_analysis.hpp"

namespace pl {

class ContinuityMonitor {
 public:
  // One evaluated filling to analyse, with the name the panel gives it ("" when there is one).
  struct Input {
    std::string label;
    const SceneSurfaces* surfaces = nullptr;
  };
  struct Filling {
    std::string label;
    SceneReport report;
    int worst = -1;  // index into report.edges of the largest normal angle, -1 without edges
  };

  // Brings the figures up to `revision` of `scene` for these fillings. Returns true when they
  // were recomputed (a new revision, or other fillings: the comparison turned on or off).
  bool follow(const Scene& scene, std::span<const Input> fillings, uint64_t revision);
  // One filling (the scene's own).
  bool follow(const Scene& scene, const SceneSurfaces& surfaces, uint64_t revision);
  // A new document: the next follow() recomputes whatever the revision.
  void reset() { revision_ = UINT64_MAX; }

  const std::vector<Filling>& fillings() const { return fillings_; }
  // The first filling's report and worst edge (an empty report before any follow()).
  const SceneReport& report() const;
  int worst() const { return fillings_.empty() ? -1 : fillings_[0].worst; }
  int worst_edge() const;

  // Indices into fillings()[f].report.edges of the edges whose normal angle exceeds
  // `threshold_deg`, largest first.
  std::vector<int> warnings(std::size_t f, double threshold_deg) const;
  // The network edge to highlight in the view of filling f: its worst edge when that exceeds the
  // threshold, else -1 (no false alarm).
  int warned_edge(std::size_t f, double threshold_deg) const;
  // Whether any filling has an edge over the threshold.
  bool any_warning(double threshold_deg) const;

 private:
  std::vector<Filling> fillings_;
  std::vector<std::string> labels_;
  uint64_t revision_ = UINT64_MAX;
};

}  // namespace pl
