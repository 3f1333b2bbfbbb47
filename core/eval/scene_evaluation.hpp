// The live evaluation of a scene: the one engine that follows every edit incrementally.
//
// sync() brings it up to date with the scene after any edit, at a cost that follows what the
// edit changed, not the size of the scene:
//   - the network goes through IncrementalFilling, which compares it with the copy it last
//     filled and re-fills only the faces whose data changed (a point move: the faces at the
//     moved vertex or handle; a topology edit: new and changed faces, the others keep their
//     patches whatever their new index);
//   - a refilled face whose patch keeps its type and domain follows it point by point: only the
//     control points that differ are moved, together (PatchEvaluator::move_control_points: an
//     axpy each with a cached influence column, geometry once per sample); a face with a new
//     layout (a split edge gave it a side) or a new face is evaluated from scratch; a deleted
//     face's evaluator is dropped; an unchanged face keeps its evaluator and samples;
//   - an interior edit of a GB face (its offsets alone changed: a free point dragged or typed)
//     moves the free points whose offsets changed on the face's patch as it is, without a patch
//     build: an axpy each with the point's cached influence column (delta phi_p and its
//     derivatives), then the geometry of the samples it touches;
//   - when the caller knows an edit changed only GB interior offsets (InteriorEdit: the document
//     records what each of its revisions changed), only the named faces are looked at: no scan
//     of the network or of the surface list, so a free-point drag costs the same on 24 or 1,536
//     faces;
//   - explicit patches are compared by identity (the document copies a patch on write, and the
//     evaluation keeps a reference to the one it followed, so an address cannot be reused):
//     only replaced patches are compared point by point.
// Each surface may have its own density (set_densities): the editor chooses them from the
// faces' sizes on screen.
#pragma once

#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/eval/scene_surfaces.hpp"
#include "core/network/incremental_filling.hpp"

namespace pl {

struct SyncStats {
  // Surfaces (indices after the sync) whose samples changed or that are not the surface that
  // had this index before: what a renderer re-uploads and a curve cache resamples.
  std::vector<int> changed_surfaces;
  // Per surface after the sync: its index before, or -1 for a new one (a surface that followed a
  // new patch point by point keeps its index; one evaluated from scratch is new).
  std::vector<int> previous_surface;
  std::size_t moved_points = 0;      // control points moved incrementally
  std::size_t rebuilt_surfaces = 0;  // surfaces evaluated from scratch
  bool renumbered = false;           // surfaces were added, removed or renumbered
};

// What an edit changed, when the caller knows it for sure: only the GB interior offsets of these
// network faces; everything else is as the previous sync saw it. A promise the network does not
// bear out (a listed face changed in more than its offsets, different counts) is noticed and the
// sync falls back to comparing everything; anything changed outside the list is not noticed.
struct InteriorEdit {
  std::vector<int> faces;
};

class SceneEvaluation {
 public:
  // Evaluates every surface at `density` (>= 1), keeping each sample as `storage` says. Throws
  // DataError like evaluate_scene.
  SceneEvaluation(const Scene& scene, int density, std::optional<FaceScheme> scheme,
                  std::string source = "scene", SampleStorage storage = SampleStorage::Jets);

  const SceneSurfaces& surfaces() const { return surfaces_; }
  int density() const { return density_; }  // of new surfaces
  std::optional<FaceScheme> scheme() const { return scheme_; }
  SampleStorage storage() const { return storage_; }

  // Follows the scene's current state. Throws DataError if the edited network cannot be filled;
  // the evaluation is then left as it was. `known`: what changed since the previous sync, when
  // the caller knows (above).
  SyncStats sync(const Scene& scene, const InteriorEdit* known = nullptr);

  // Re-evaluates the surfaces whose density differs from densities[i] (one entry per surface,
  // each >= 1) at that density; the others are untouched. New surfaces of later syncs get
  // density(). Returns the surfaces it re-evaluated.
  SyncStats set_densities(std::span<const int> densities);

  // The network's filling: topology, tangent planes and the projected vertices (also in
  // surfaces().projected_vertices). Empty without a network.
  const IncrementalFilling& filling() const { return filling_; }

  TessellationCache& cache() { return cache_; }

 private:
  // The scene patch behind a run of explicit surfaces, kept alive so its address stays unique.
  struct PatchSource {
    std::shared_ptr<const Patch> patch;
    std::string name;
    std::size_t surfaces = 0;  // how many surfaces (pieces) it gave
  };
  std::unique_ptr<PatchEvaluator> make_evaluator(std::shared_ptr<Patch> patch, int density);
  void sync_faces(const FillingUpdate& up, std::vector<SceneSurface>& out, SyncStats& stats);
  // Whether each of `faces` is the surface of the same index (no renumbering pending).
  bool faces_in_place(std::span<const int> faces) const;
  // Moves face f's free points to its offsets now (an interior edit); whether its samples changed.
  bool follow_offsets(SceneSurface& s, int f, SyncStats& stats);
  // The interior edits of update_interior(), in place: each face takes its offsets from
  // `network` as it is followed (a face that fails to follow gets its old offsets back, so the
  // next sync tries it again).
  void sync_interior(const FillingUpdate& up, const Network& network, SyncStats& stats);
  void sync_patches(const Scene& scene, std::vector<SceneSurface>& out, SyncStats& stats);

  TessellationCache cache_;
  int density_;
  std::optional<FaceScheme> scheme_;
  std::string source_;
  SampleStorage storage_;
  IncrementalFilling filling_;
  std::vector<PatchSource> patch_sources_;
  SceneSurfaces surfaces_;
};

}  // namespace pl
