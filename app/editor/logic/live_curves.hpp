// The patch borders of a view and the curvature combs of its network curves, borders and free
// curves, kept
// once for every density of the view: they depend on the patches, not on the tessellation, so
// the coarse (drag) and fine (rest) evaluations share them. follow() recomputes only the surfaces
// an evaluation's sync changed; without combs no comb work is done at all (the borders are bare
// polylines, no teeth, no corner extrapolation) and turning combs on, or a new tooth count,
// resamples the curves without re-evaluating any surface. GUI-free.
#pragma once

#include <cstdint>
#include <vector>

#include "core/eval/scene_surfaces.hpp"
#include "core/scene/scene.hpp"
#include "render/draw_scene.hpp"

namespace pl {

class LiveCurves {
 public:
  // Nothing computed until the first follow(). teeth: tooth intervals per curve (>= 1).
  LiveCurves(bool combs, int teeth);

  // Combs on or off and the tooth count; applied by the next follow() (everything resampled).
  void configure(bool combs, int teeth);

  // Brings the curves up to `surfaces` (of `scene`), an evaluation at document revision `to`
  // whose last sync came from revision `from` and changed the surfaces `changed`. Incremental
  // when the curves were at `from` with the same settings; otherwise every curve is resampled.
  // Returns true when the curves changed (serial() too). With the network's `topology`, a
  // network face's bare border (no comb) is its edges' polylines, the same curves as the
  // patch's sides (a face interpolates its edges) for a few Bézier evaluations instead of the
  // surface jets: 1,536 faces' borders take milliseconds instead of most of a second.
  bool follow(const Scene& scene, const SceneSurfaces& surfaces, uint64_t from, uint64_t to,
              const std::vector<int>& changed, const NetworkTopology* topology = nullptr);

  bool combs() const { return combs_; }
  int teeth() const { return teeth_; }
  // Increases whenever the curves change: a GPU copy is current while its serial matches.
  uint64_t serial() const { return serial_; }
  // Per network edge (empty without combs).
  const std::vector<CurvatureComb>& network_combs() const { return network_combs_; }
  // Per free curve of the scene, one comb per span (empty without combs). Only the curves that
  // changed since the last follow() are resampled (a drag on one curve leaves the others), and
  // of a curve whose points only moved, the spans those points touch.
  const std::vector<std::vector<CurvatureComb>>& free_curve_combs() const { return free_combs_; }
  // Free curves, and spans of them, resampled by the last follow() (for tests).
  std::size_t last_free_curves_resampled() const { return last_free_resampled_; }
  std::size_t last_free_spans_resampled() const { return last_free_spans_resampled_; }
  // Per surface, per domain side: the border's points and, with combs, its teeth.
  const std::vector<std::vector<CurvatureComb>>& borders() const { return borders_; }
  // Per surface: a network face (its border combs are its edges').
  const std::vector<bool>& on_network() const { return on_network_; }

  // Flattened pointers for GpuScene::update_curves (valid until the next follow()).
  std::vector<const CurvatureComb*> network_comb_refs() const;
  std::vector<const CurvatureComb*> border_refs() const;
  std::vector<const CurvatureComb*> free_comb_refs() const;
  std::vector<bool> border_on_network() const;

 private:
  bool combs_;
  int teeth_;
  bool stale_ = true;  // settings changed, or nothing computed yet
  uint64_t revision_ = 0, serial_ = 0;
  std::vector<CurvatureComb> network_combs_;
  std::vector<SceneCurve> combed_curves_;  // the free curves as free_combs_ were made from
  std::vector<std::vector<CurvatureComb>> free_combs_;
  std::size_t last_free_resampled_ = 0, last_free_spans_resampled_ = 0;
  bool follow_free_curves(const std::vector<SceneCurve>& curves);
  std::vector<std::vector<CurvatureComb>> borders_;
  std::vector<bool> on_network_;
};

}  // namespace pl
