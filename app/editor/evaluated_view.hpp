// One filling of the document's scene (its own schemes, or all-Gregory / all-GB for the
// comparison) kept live at two densities, each with its GPU copy: while a drag is under way the
// coarse evaluation follows the document and is drawn; on release the fine one catches up
// (moving only the changed control points) and is drawn again. The borders and curvature combs
// (LiveCurves) are shared by both densities and uploaded to the GPU copy shown when they
// change. Needs a current GL context.
#pragma once

#include <optional>
#include <string>

#include "app/document/document.hpp"
#include "app/editor/logic/live_curves.hpp"
#include "app/editor/logic/live_surfaces.hpp"
#include "render/display_settings.hpp"
#include "render/gpu_scene.hpp"

namespace pl {

class EvaluatedView {
 public:
  // Throws DataError when the scene cannot be evaluated. combs, comb_teeth: as configure_combs.
  EvaluatedView(const Document& doc, std::optional<FaceScheme> scheme, int coarse_density,
                int fine_density, bool combs = false,
                int comb_teeth = DisplaySettings().comb_teeth);

  // Follows the document; returns true when what is drawn changed. Throws DataError when the
  // edited network cannot be filled (the view keeps its last state).
  bool follow(const Document& doc);

  // Curvature combs on or off and their tooth count: applied by the next follow(), which
  // resamples the curves of the surfaces shown without re-evaluating them (no comb work while
  // combs are off).
  void configure_combs(bool combs, int teeth) { curves_.configure(combs, teeth); }

  const LiveSurfaces& shown() const { return coarse_shown_ ? coarse_ : fine_; }
  const GpuScene& gpu() const { return coarse_shown_ ? gpu_coarse_ : gpu_fine_; }
  const LiveSurfaces& fine() const { return fine_; }
  const LiveCurves& curves() const { return curves_; }
  bool settled() const { return !coarse_shown_; }
  std::optional<FaceScheme> scheme() const { return scheme_; }
  double last_eval_ms() const { return last_eval_ms_; }

 private:
  // Brings the curves up to `live` (last synced from revision `from`, changing `changed`) and
  // uploads them to `gpu` if its copy is older. Returns true when something was uploaded.
  bool follow_curves(const Document& doc, const LiveSurfaces& live, uint64_t from,
                     const std::vector<int>& changed, GpuScene& gpu, uint64_t& gpu_serial);

  std::optional<FaceScheme> scheme_;
  LiveSurfaces fine_, coarse_;
  LiveCurves curves_;
  GpuScene gpu_fine_, gpu_coarse_;
  uint64_t fine_revision_, coarse_revision_;
  uint64_t fine_curves_serial_ = UINT64_MAX, coarse_curves_serial_ = UINT64_MAX;
  bool coarse_shown_ = false;
  double last_eval_ms_ = 0;
};

}  // namespace pl
