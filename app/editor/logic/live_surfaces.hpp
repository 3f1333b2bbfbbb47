// One live evaluation of the document's scene at one density and scheme, with the plain arrays
// the renderer draws. sync() follows an edit incrementally (SceneEvaluation re-fills and moves
// only what changed) and refreshes only what the edit touched: the meshes of surfaces that
// changed (the GPU re-uploads only those: their revision numbers change, the others' do not;
// after a topology edit the unchanged meshes move to their surfaces' new indices), the network
// curves of edges whose control points moved, and the positions of the control points that
// moved. A drag frame costs the same on a network of 24 or of 1,536 faces. Borders and curvature
// combs do not depend on the density: LiveCurves keeps them once for every density. Each surface
// may have its own density (set_densities). GUI-free.
#pragma once

#include <array>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "app/editor/logic/free_curve_lines.hpp"
#include "app/editor/logic/scene_points.hpp"
#include "core/eval/scene_evaluation.hpp"

namespace pl {

class LiveSurfaces {
 public:
  // Throws DataError like evaluate_scene. `revision`: the document revision `scene` is.
  LiveSurfaces(const Scene& scene, int density, std::optional<FaceScheme> scheme,
               const std::string& source, uint64_t revision = 0,
               SampleStorage storage = SampleStorage::Jets);

  // Brings the evaluation up to `scene` (revision `revision` of the document). Returns the
  // indices of surfaces whose meshes (and patches) changed. Throws DataError when the edited
  // network cannot be filled; the previous state is kept. `known`: what changed since the
  // previous sync when the document knows it (SceneEvaluation::sync).
  std::vector<int> sync(const Scene& scene, uint64_t revision, const InteriorEdit* known = nullptr);

  // Evaluates surface i at densities[i] (one per surface) where that differs from its density
  // now; returns the surfaces re-evaluated.
  std::vector<int> set_densities(std::span<const int> densities);
  // The density of each surface.
  std::vector<int> densities() const;
  // How many segments each network curve is drawn with (one per edge; 64 by default, fewer for
  // an edge a few pixels long on screen). Returns true when a curve changed.
  bool set_curve_segments(std::vector<int> per_edge);

  uint64_t synced_revision() const { return revision_; }
  int density() const { return evaluation_.density(); }  // of new surfaces
  std::optional<FaceScheme> scheme() const { return evaluation_.scheme(); }
  const SceneSurfaces& surfaces() const { return evaluation_.surfaces(); }
  const SceneEvaluation& evaluation() const { return evaluation_; }
  const DrawScene& draw() const { return draw_; }
  const ScenePoints& points() const { return points_; }
  // Changes whenever the points are listed again (their indices may mean other points).
  uint64_t points_layout() const { return points_layout_; }
  // Which points are left out of the drawing and the picking (net_thinning.hpp); empty: none.
  void set_hidden_points(std::vector<uint8_t> hidden) { points_.hidden = std::move(hidden); }
  double last_sync_ms() const { return last_sync_ms_; }
  std::size_t sample_count() const;

 private:
  void rebuild_overlays(const Scene& scene);
  // The overlays after an edit that kept every count (a drag): only moved points and curves are
  // recomputed. False when the layout changed (then everything is rebuilt).
  bool update_overlays(const Scene& scene, const std::vector<int>& changed);
  int segments_of(std::size_t edge) const;
  void update_meshes(const SyncStats& stats);

  SceneEvaluation evaluation_;
  DrawScene draw_;
  ScenePoints points_;
  // Every edge's control points as last drawn.
  std::vector<std::array<Vec3, 4>> edge_points_;
  FreeCurveLines free_lines_;
  std::vector<EdgeCrossTangents> cross_scratch_;  // the free points' update (scene_points.hpp)
  std::size_t curve_points_at_ = 0;               // the first free-curve point in points_
  std::vector<int> curve_segments_;               // per edge, or empty: all kCurveSegments
  uint64_t revision_ = 0;
  uint64_t points_layout_ = 0;
  double last_sync_ms_ = 0;
};

}  // namespace pl
