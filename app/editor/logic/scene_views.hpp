// The evaluated fillings the editor shows: the scene's own (always), and for the comparison one
// filling per pane, every face filled by the pane's scheme where the face takes it
// (compare_layout.hpp: 2, 3, 4 or 6 panes of any schemes), each an EvaluatedView (two densities
// with their GPU copies) that follows every edit incrementally; and the GPU copies of the
// comparison's difference colouring (every pane but the base's, coloured by its distance to the
// base pane's filling). The drawn copies are made by the factory given (the window's GPU buffers;
// none without a window: view_copy.hpp). A scene that cannot be evaluated leaves no view and an
// error() to show instead. Evaluation runs on a worker thread (a 1,536-face network takes seconds):
// the window keeps repainting and shows the progress; the drawn copies are made on the caller's
// thread in poll().
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
#include "app/editor/logic/compare_layout.hpp"
#include "app/editor/logic/difference_field.hpp"
#include "app/editor/logic/evaluated_view.hpp"
#include "app/editor/logic/preferences.hpp"

namespace pl {

class SceneViews {
 public:
  explicit SceneViews(ViewCopyFactory copies = {}) : copies_(std::move(copies)) {}
  ~SceneViews();  // waits for a worker still evaluating
  SceneViews(const SceneViews&) = delete;
  SceneViews& operator=(const SceneViews&) = delete;

  // Evaluates the document afresh on a worker thread (compare is honoured only for a scene
  // with a network; its panes are prefs' compare_schemes); until poll() takes the result the views
  // are not ready() and loading() holds. Waits up to `wait` for the worker, so a small scene is
  // shown in the same frame.
  void rebuild(const Document& doc, const Preferences& prefs, bool compare,
               std::chrono::milliseconds wait = std::chrono::milliseconds(150));
  // Takes the worker's result when it is there: gives it to the drawn copies and makes the views
  // ready, or keeps the error. Returns true when it did.
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
  // Why the comparison asked for is not shown (a pane's scheme cannot fill the network; the
  // scene's own view is), or "".
  const std::string& compare_error() const { return compare_error_; }
  // Comparing, or evaluating the comparison.
  bool compare() const { return compare_ || (job_ && job_->compare); }
  int panels() const { return compare_ ? int(compare_views_.size()) : 1; }
  // The panes' schemes and base (meaningful while compare()).
  const CompareSetup& setup() const { return setup_; }
  // Another base among the panes' schemes: the distances follow, nothing is re-evaluated.
  void set_base(FaceScheme base);
  // The view drawn in panel i (the main view when not comparing). ready() must hold.
  const EvaluatedView& panel(int i) const;
  // The scene's own filling; while comparing it is not followed (not shown): own() brings it
  // up to the document first (an export while comparing). Throws DataError like follow().
  const EvaluatedView* main() const { return main_.get(); }
  const EvaluatedView& own(const Document& doc);
  // Every view shown is at its fine density (after a drag: all panes exact).
  bool settled() const;
  // The time of the last evaluation: the worker's of the document (from rebuild() on, until
  // taken: 0), then each follow() that changed what is drawn.
  double last_eval_ms() const { return last_eval_ms_; }

  // The curvature colour range common to all panels (equal colours mean equal curvature), for
  // the document at `revision`: the fixed one, or the automatic one of the surfaces shown,
  // recomputed only when they or the settings change (it visits every sample). Only the
  // curvature modes use it; others get a placeholder without the cost.
  ColorRange colour_range(const DisplaySettings& display, uint64_t revision);

  // The comparison's difference colouring (every pane but the base's coloured by its distance to
  // the base pane's filling).
  bool difference = false;
  bool showing_difference() const { return compare_ && difference; }
  // Whether pane `panel` shows distances (not the base pane).
  bool shows_distance(int panel) const {
    return showing_difference() && panel >= 0 && panel < panels() && panel != setup_.base_pane();
  }
  // The drawn copy of pane `panel`'s difference colouring for this revision (recomputed when the
  // document or the densities shown changed); null when that pane shows no distances.
  const ViewCopy* difference_scene(uint64_t revision, int panel);
  // One symmetric range for every pane's distances (the largest |distance| of any), and that
  // largest distance: from the fields last computed.
  double difference_range() const;
  double difference_max() const;
  // The probe reads it; null for a pane without distances.
  const DifferenceField* difference_field(int panel) const;

 private:
  // The evaluation on the worker: progress written there, read here.
  struct Job {
    std::mutex mutex;
    double fraction = 0;
    std::string stage = "reading";
    std::vector<ViewEvaluation> views;  // main, then one per pane when comparing
    std::string error;
    std::string pane_error;  // the first pane that could not be evaluated, and why
    bool compare = false;
    CompareSetup setup;
    double eval_ms = 0;  // the worker's evaluation, all views
  };
  std::shared_ptr<Job> job_;
  std::future<void> worker_;
  std::vector<std::future<void>> abandoned_;  // replaced before they finished

  std::unique_ptr<EvaluatedView> main_;
  std::vector<std::unique_ptr<EvaluatedView>> compare_views_;  // one per pane
  CompareSetup setup_;
  bool compare_ = false;
  std::string error_, compare_error_;
  double last_eval_ms_ = 0;
  std::vector<DifferenceField> fields_;  // one per pane (the base pane's stays empty)
  // The automatic curvature range: of the surfaces shown at this key.
  struct RangeKey {
    uint64_t revision = 0;
    bool settled = false;
    int panels = 1;
    CurvatureKind kind = CurvatureKind::Mean;
    double percentile = 0;
    bool operator==(const RangeKey&) const = default;
  };
  DerivedFrom<RangeKey> range_;
  ColorRange range_value_{-1, 1};
  ViewCopyFactory copies_;
  std::vector<std::unique_ptr<ViewCopy>> difference_copies_;  // one per pane
};

}  // namespace pl
