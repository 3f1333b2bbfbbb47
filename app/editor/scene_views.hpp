// The evaluated fillings the editor shows: the scene's own (always), and for the comparison its
// all-Gregory and all-GB fillings side by side, each an EvaluatedView (two densities with their
// GPU copies); and the GPU copy of the comparison's difference colouring. Needs a current GL
// context. A scene that cannot be evaluated leaves no view and an error() to show instead.
// Evaluation runs on a worker thread (a 1,536-face network takes seconds): the window keeps
// repainting and shows the progress; the upload happens on the GL thread in poll().
#pragma once

#include <chrono>
#include <functional>
#include <future>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "app/document/document.hpp"
#include "app/editor/evaluated_view.hpp"
#include "app/editor/logic/difference_field.hpp"
#include "app/editor/logic/preferences.hpp"

namespace pl {

class SceneViews {
 public:
  SceneViews() = default;
  ~SceneViews();  // waits for a worker still evaluating
  SceneViews(const SceneViews&) = delete;
  SceneViews& operator=(const SceneViews&) = delete;

  // Evaluates the document afresh on a worker thread (compare is honoured only for a scene
  // with a network); until poll() takes the result the views are not ready() and loading()
  // holds. Waits up to `wait` for the worker, so a small scene is shown in the same frame.
  void rebuild(const Document& doc, const Preferences& prefs, bool compare,
               std::chrono::milliseconds wait = std::chrono::milliseconds(150));
  // Takes the worker's result when it is there: uploads it (the GL context's thread) and makes
  // the views ready, or keeps the error. Returns true when it did.
  bool poll();
  bool loading() const { return job_ != nullptr; }
  // How far the worker is (0 to 1) and what it does, while loading().
  double load_fraction() const;
  std::string load_stage() const;
  // Follows the document's edits and the comb settings. Returns true when what is drawn
  // changed. Throws DataError when an edit cannot be filled (the views keep their last state).
  bool follow(const Document& doc, const DisplaySettings& display);
  // Each view's face densities and curve segments for their sizes on screen
  // (EvaluatedView::fit_to_screen). Returns true when what is drawn changed.
  bool fit_to_screen(const std::function<double(const Vec3& centre, double radius)>& pixels,
                     const Document& doc);

  // Every view's control net thinned for its size on screen, `focus` always shown
  // (EvaluatedView::show_net).
  void show_net(const NetFocus& focus, double point_px, const Document& doc);

  bool ready() const { return main_ != nullptr; }
  const std::string& error() const { return error_; }
  // Comparing, or evaluating the comparison.
  bool compare() const { return compare_ || (job_ && job_->compare); }
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
  // The evaluation on the worker: progress written there, read here.
  struct Job {
    std::mutex mutex;
    double fraction = 0;
    std::string stage = "reading";
    std::vector<ViewEvaluation> views;  // main, then Gregory and GB when comparing
    std::string error;
    bool compare = false;
  };
  std::shared_ptr<Job> job_;
  std::future<void> worker_;
  std::vector<std::future<void>> abandoned_;  // replaced before they finished

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
