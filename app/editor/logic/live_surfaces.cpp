#include "app/editor/logic/live_surfaces.hpp"

#include <chrono>

namespace pl {

LiveSurfaces::LiveSurfaces(const Scene& scene, int density, std::optional<FaceScheme> scheme,
                           const std::string& source, uint64_t revision)
    : evaluation_(scene, density, scheme, source), revision_(revision) {
  for (const SceneSurface& s : evaluation_.surfaces().surfaces)
    draw_.surfaces.push_back(make_surface_mesh(*s.evaluator, s.name));
  points_ = collect_scene_points(scene, evaluation_.surfaces());
  fill_overlays(scene, points_, draw_);
}

std::vector<int> LiveSurfaces::sync(const Scene& scene, uint64_t revision) {
  const auto t0 = std::chrono::steady_clock::now();
  const SyncStats stats = evaluation_.sync(scene);
  const auto& surfaces = evaluation_.surfaces().surfaces;
  if (draw_.surfaces.size() != surfaces.size()) {
    draw_.surfaces.clear();
    for (const SceneSurface& s : surfaces)
      draw_.surfaces.push_back(make_surface_mesh(*s.evaluator, s.name));
  } else {
    for (int i : stats.changed_surfaces)
      draw_.surfaces[i] = make_surface_mesh(*surfaces[i].evaluator, surfaces[i].name);
  }
  points_ = collect_scene_points(scene, evaluation_.surfaces());
  fill_overlays(scene, points_, draw_);
  revision_ = revision;
  last_sync_ms_ =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return stats.changed_surfaces;
}

}  // namespace pl
