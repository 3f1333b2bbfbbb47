// One filling of the document's scene (its own schemes, or all-Gregory / all-GB for the
// comparison) kept live at two densities, each with its GPU copy: while a drag is under way the
// coarse evaluation follows the document and is drawn; on release the fine one catches up
// (moving only the changed control points) and is drawn again. Needs a current GL context.
#pragma once

#include <optional>
#include <string>

#include "app/document/document.hpp"
#include "app/editor/logic/live_surfaces.hpp"
#include "render/gpu_scene.hpp"

namespace pl {

class EvaluatedView {
 public:
  // Throws DataError when the scene cannot be evaluated.
  EvaluatedView(const Document& doc, std::optional<FaceScheme> scheme, int coarse_density,
                int fine_density, int comb_teeth = DisplaySettings().comb_teeth);

  // Follows the document; returns true when what is drawn changed. Throws DataError when the
  // edited network cannot be filled (the view keeps its last state).
  bool follow(const Document& doc);

  const LiveSurfaces& shown() const { return coarse_shown_ ? coarse_ : fine_; }
  const GpuScene& gpu() const { return coarse_shown_ ? gpu_coarse_ : gpu_fine_; }
  const LiveSurfaces& fine() const { return fine_; }
  bool settled() const { return !coarse_shown_; }
  std::optional<FaceScheme> scheme() const { return scheme_; }
  double last_eval_ms() const { return last_eval_ms_; }

 private:
  std::optional<FaceScheme> scheme_;
  LiveSurfaces fine_, coarse_;
  GpuScene gpu_fine_, gpu_coarse_;
  uint64_t fine_revision_, coarse_revision_;
  bool coarse_shown_ = false;
  double last_eval_ms_ = 0;
};

}  // namespace pl
