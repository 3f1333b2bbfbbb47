#include "app/editor/logic/continuity_monitor.hpp"

namespace pl {

bool ContinuityMonitor::follow(const Scene& scene, const SceneSurfaces& surfaces,
                               uint64_t revision) {
  if (revision == revision_) return false;
  revision_ = revision;
  report_ = analyze_scene(scene, surfaces);
  worst_ = -1;
  for (std::size_t i = 0; i < report_.edges.size(); ++i)
    if (worst_ < 0 ||
        report_.edges[i].max_normal_angle_deg > report_.edges[worst_].max_normal_angle_deg)
      worst_ = static_cast<int>(i);
  return true;
}

}  // namespace pl
