// One live evaluation of the document's scene at one density and scheme, with the plain arrays
// the renderer draws. sync() follows an edit incrementally (SceneEvaluation moves only changed
// control points) and refreshes only the meshes of surfaces that changed, so the GPU re-uploads
// only those (their revision numbers change, the others' do not). Borders and curvature combs
// do not depend on the density: LiveCurves keeps them once for every density. GUI-free.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "app/editor/logic/scene_points.hpp"
#include "core/eval/scene_evaluation.hpp"

namespace pl {

class LiveSurfaces {
 public:
  // Throws DataError like evaluate_scene. `revision`: the document revision `scene` is.
  LiveSurfaces(const Scene& scene, int density, std::optional<FaceScheme> scheme,
               const std::string& source, uint64_t revision = 0);

  // Brings the evaluation up to `scene` (revision `revision` of the document). Returns the
  // indices of surfaces whose meshes (and patches) changed. Throws DataError when the edited
  // network cannot be filled; the previous state is kept.
  std::vector<int> sync(const Scene& scene, uint64_t revision);

  uint64_t synced_revision() const { return revision_; }
  int density() const { return evaluation_.density(); }
  std::optional<FaceScheme> scheme() const { return evaluation_.scheme(); }
  const SceneSurfaces& surfaces() const { return evaluation_.surfaces(); }
  const DrawScene& draw() const { return draw_; }
  const ScenePoints& points() const { return points_; }
  double last_sync_ms() const { return last_sync_ms_; }

 private:
  SceneEvaluation evaluation_;
  DrawScene draw_;
  ScenePoints points_;
  uint64_t revision_ = 0;
  double last_sync_ms_ = 0;
};

}  // namespace pl
