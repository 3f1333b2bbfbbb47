// A live evaluation of a scene that follows edits incrementally.
//
// sync() brings it up to date with the scene after any edit: network faces are re-filled (the
// Chiyokura–Kimura construction is cheap next to evaluation) and every surface's control points
// are compared with the ones its evaluator holds; only points that differ are moved, together
// (PatchEvaluator::move_control_points: one axpy each, geometry once per sample). A face whose
// domain or point count changed (a concave domain follows its boundary) is re-evaluated from
// scratch. So an edit costs in proportion to what it really changed, whoever produced the patches.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/eval/scene_surfaces.hpp"

namespace pl {

struct SyncStats {
  std::vector<int> changed_surfaces;  // indices into surfaces().surfaces
  std::size_t moved_points = 0;       // control points moved incrementally
  std::size_t rebuilt_surfaces = 0;   // surfaces re-evaluated from scratch
};

class SceneEvaluation {
 public:
  // Throws DataError like evaluate_scene.
  SceneEvaluation(const Scene& scene, int density, std::optional<FaceScheme> scheme,
                  std::string source = "scene");

  const SceneSurfaces& surfaces() const { return surfaces_; }
  int density() const { return density_; }
  std::optional<FaceScheme> scheme() const { return scheme_; }

  // Follows the scene's current state. Throws DataError if the edited network cannot be filled;
  // the evaluation is then left as it was.
  SyncStats sync(const Scene& scene);

  // Prepares the influence columns of the points a drag of these surfaces' points will move.
  TessellationCache& cache() { return cache_; }

 private:
  TessellationCache cache_;
  int density_;
  std::optional<FaceScheme> scheme_;
  std::string source_;
  SceneSurfaces surfaces_;
};

}  // namespace pl
