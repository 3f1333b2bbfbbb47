#include "app/editor/logic/live_surfaces.hpp"

#include <chrono>

namespace pl {

LiveSurfaces::LiveSurfaces(const Scene& scene, int density, std::optional<FaceScheme> scheme,
                           const std::string& source, int comb_teeth)
    : evaluation_(scene, density, scheme, source), comb_teeth_(comb_teeth) {
  for (const SceneSurface& s : evaluation_.surfaces().surfaces) {
    draw_.surfaces.push_back(make_surface_mesh(*s.evaluator, s.name));
    border_combs_.push_back(border_combs(s, comb_teeth_));
  }
  points_ = collect_scene_points(scene, evaluation_.surfaces());
  fill_overlays(scene, points_, comb_teeth_, draw_);
  fill_borders(evaluation_.surfaces(), border_combs_, draw_);
}

std::vector<int> LiveSurfaces::sync(const Scene& scene, uint64_t revision) {
  const auto t0 = std::chrono::steady_clock::now();
  const SyncStats stats = evaluation_.sync(scene);
  const auto& surfaces = evaluation_.surfaces().surfaces;
  if (draw_.surfaces.size() != surfaces.size()) {
    draw_.surfaces.clear();
    border_combs_.clear();
    for (const SceneSurface& s : surfaces) {
      draw_.surfaces.push_back(make_surface_mesh(*s.evaluator, s.name));
      border_combs_.push_back(border_combs(s, comb_teeth_));
    }
  } else {
    for (int i : stats.changed_surfaces) {
      draw_.surfaces[i] = make_surface_mesh(*surfaces[i].evaluator, surfaces[i].name);
      border_combs_[i] = border_combs(surfaces[i], comb_teeth_);
    }
  }
  points_ = collect_scene_points(scene, evaluation_.surfaces());
  fill_overlays(scene, points_, comb_teeth_, draw_);
  fill_borders(evaluation_.surfaces(), border_combs_, draw_);
  revision_ = revision;
  last_sync_ms_ =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return stats.changed_surfaces;
}

}  // namespace pl
