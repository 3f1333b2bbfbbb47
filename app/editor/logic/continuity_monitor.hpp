// The Continuity panel's figures: analyze_scene of the fine (at rest) surfaces, per shared edge
// the G0 gap, the G1 normal angle and the mean-curvature jump, and which edge is worst. They are
// recomputed once per document revision, only from settled surfaces: analysing every drag step
// would cost more than the drag itself. GUI-free and unit-tested.
#pragma once

#include <cstdint>

#include "core/analysis/scene_analysis.hpp"

namespace pl {

class ContinuityMonitor {
 public:
  // Brings the report up to `revision` of `scene`, whose fine evaluation is `surfaces`. Returns
  // true when it was recomputed.
  bool follow(const Scene& scene, const SceneSurfaces& surfaces, uint64_t revision);
  // A new document: the next follow() recomputes whatever the revision.
  void reset() { revision_ = UINT64_MAX; }

  const SceneReport& report() const { return report_; }
  // Index into report().edges of the edge with the largest normal angle, or -1 (no shared edge).
  int worst() const { return worst_; }
  // The network edge of worst(), or -1.
  int worst_edge() const { return worst_ < 0 ? -1 : report_.edges[worst_].edge; }

 private:
  SceneReport report_;
  uint64_t revision_ = UINT64_MAX;
  int worst_ = -1;
};

}  // namespace pl
