#include "core/eval/scene_evaluation.hpp"

namespace pl {

SceneEvaluation::SceneEvaluation(const Scene& scene, int density, std::optional<FaceScheme> scheme,
                                 std::string source)
    : density_(density), scheme_(scheme), source_(std::move(source)) {
  surfaces_ = evaluate_scene(scene, density_, scheme_, cache_, source_);
}

namespace {

// Moves the evaluator's patch onto `target` point by point; false if the structure differs.
bool follow(PatchEvaluator& ev, const Patch& target, SyncStats& stats) {
  const Patch& current = ev.patch();
  if (current.type() != target.type() || current.size() != target.size() ||
      current.domain().key() != target.domain().key())
    return false;
  std::vector<PatchEvaluator::PointMove> moves;
  for (std::size_t k = 0; k < target.size(); ++k)
    if (current.control_point(k) != target.control_point(k))
      moves.push_back({k, target.control_point(k)});
  ev.move_control_points(moves);
  stats.moved_points += moves.size();
  return true;
}

}  // namespace

SyncStats SceneEvaluation::sync(const Scene& scene) {
  SyncStats stats;
  const std::size_t faces = scene.network ? scene.network->faces.size() : 0;
  std::vector<std::vector<std::shared_ptr<Patch>>> pieces;
  std::size_t surface_count = faces;
  for (const ScenePatch& sp : scene.patches) {
    pieces.push_back(surface_pieces_of(*sp.patch));
    surface_count += pieces.back().size();
  }
  if (surface_count != surfaces_.surfaces.size()) {
    // Surfaces were added or removed: start again (rare, not on the drag path).
    SceneSurfaces fresh = evaluate_scene(scene, density_, scheme_, cache_, source_);
    surfaces_ = std::move(fresh);
    for (std::size_t s = 0; s < surfaces_.surfaces.size(); ++s)
      stats.changed_surfaces.push_back(int(s));
    stats.rebuilt_surfaces = surfaces_.surfaces.size();
    return stats;
  }
  std::vector<std::pair<int, std::shared_ptr<Patch>>> targets;  // (surface index, new patch)
  if (scene.network) {
    const NetworkTopology topo = validate_network(*scene.network, source_);
    NetworkFilling filling = fill_network(*scene.network, topo, scheme_, source_);
    surfaces_.projected_vertices = std::move(filling.projected_vertices);
    for (FacePatch& fp : filling.faces)
      for (std::size_t s = 0; s < surfaces_.surfaces.size(); ++s)
        if (surfaces_.surfaces[s].face == fp.face)
          targets.emplace_back(int(s), std::move(fp.patch));
  }
  std::vector<std::size_t> next_piece(scene.patches.size(), 0);
  for (std::size_t s = 0; s < surfaces_.surfaces.size(); ++s) {
    const int p = surfaces_.surfaces[s].patch;
    if (p >= 0) targets.emplace_back(int(s), pieces.at(p).at(next_piece[p]++));
  }
  for (auto& [s, patch] : targets) {
    SceneSurface& surface = surfaces_.surfaces[s];
    const uint64_t before = surface.evaluator->revision();
    if (!follow(*surface.evaluator, *patch, stats)) {
      std::shared_ptr<Patch> own = patch->clone();
      auto tess = cache_.get(own->domain(), density_);
      surface.evaluator = std::make_unique<PatchEvaluator>(std::move(own), std::move(tess));
      surface.evaluator->continue_revisions_from(before);
      ++stats.rebuilt_surfaces;
      stats.changed_surfaces.push_back(s);
    } else if (surface.evaluator->revision() != before) {
      stats.changed_surfaces.push_back(s);
    }
  }
  return stats;
}

}  // namespace pl
