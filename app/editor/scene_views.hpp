// The evaluated fillings the editor shows: the scene's own (always), and for the comparison its
// all-Gregory and all-GB fillings side by side, each an EvaluatedView (two densities with their
// GPU copies); and the GPU copy of the comparison's difference colouring. Needs a current GL
// context. A scene that cannot be evaluated leaves no view and an error() to show instead.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "app/document/document.hpp"
#include "app/editor/evaluated_view.hpp"
#include "app/editor/logic/difference_field.hpp"
#include "app/editor/logic/preferences.hpp"

namespace pl {

class SceneViews {
 public:
  // Evaluates the document afresh; compare is honoured only for a scene with a network.
  void rebuild(const Document& doc, const Preferences& prefs, bool compare);
  // Follows the document's edits and the comb settings. Returns true when what is drawn
  // changed. Throws DataError when an edit cannot be filled (the views keep their last state).
  bool follow(const Document& doc, const DisplaySettings& display);
  // Each view's face densities and curve segments for their sizes on screen
  // (EvaluatedView::fit_to_screen). Returns true when what is drawn changed.
  bool fit_to_screen(const std::function<double(const Vec3& centre, double radius)>& pixels,
                     const Document& doc);

  bool ready() const { return main_ != nullptr; }
  const std::string& error() const { return error_; }
  bool compare() const { return compare_; }
  int panels() const { return compare_ ? 2 : 1; }
  // The view drawn in panel i (the main view when not comparing). ready() must hold.
  const EvaluatedView& panel(int i) const;
  const EvaluatedView* main() const { return main_.get(); }
  bool settled() const { return main_ && main_->settled(); }
  double last_eval_ms() const { return last_eval_ms_; }

  // The curvature colour range common to all panels (equal colours mean equal curvature), for
  // the document at `revision`: the fixed one, or the automatic one of the surfaces shown,
  // recomputed only when they or the settings change (it visits every sample). Only the
  // curvature modes use it; others get a placeholder without the cost.
  ColorRange colour_range(const DisplaySettings& display, uint64_t revision);

  // The comparison's difference colouring (GB coloured by its distance to Gregory).
  bool difference = false;
  bool showing_difference() const { return compare_ && difference; }
  // The GPU copy of the difference colouring for this revision (recomputed when the document or
  // the densities shown changed); null when not comparing.
  const GpuScene* difference_scene(uint64_t revision);
  double difference_range() const { return field_.range(); }
  double difference_max() const { return field_.max_abs(); }
  const DifferenceField& difference_field() const { return field_; }  // the probe reads it

 private:
  std::unique_ptr<EvaluatedView> main_;
  std::unique_ptr<EvaluatedView> compare_views_[2];  // Gregory, GB
  bool compare_ = false;
  std::string error_;
  double last_eval_ms_ = 0;
  DifferenceField field_;
  struct RangeKey {
    uint64_t revision = UINT64_MAX;
    bool settled = false, compare = false;
    CurvatureKind kind = CurvatureKind::Mean;
    double percentile = 0;
    bool operator==(const RangeKey&) const = default;
  } range_key_;
  ColorRange range_{-1, 1};
  std::unique_ptr<GpuScene> difference_gpu_;
};

}  // namespace pl
