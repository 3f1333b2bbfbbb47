// One filling of the document's scene (its own schemes, or all-Gregory / all-GB for the
// comparison) kept live at two densities, each with its GPU copy: while a drag is under way the
// coarse evaluation follows the document and is drawn; on release the fine one catches up
// (re-filling and re-evaluating only the faces the drag changed) and is drawn again. The borders
// and curvature combs (LiveCurves) are shared by both densities and given to the drawn copy shown
// when they change. The drawn copies (view_copy.hpp) are the window's GPU buffers, or nothing
// when no window draws the view.
//
// Big networks: each view has a triangle budget. It starts at the highest density of its chain
// (fine_density, fine_density / 2, ...) at which all surfaces fit the budget, and
// fit_to_screen() then gives each face the density its size on screen asks for, within the
// budget (core/eval/density_choice.hpp), so drawing and memory stay bounded whatever the size of
// the network; density_note() says what was chosen, for the status bar. The network curves and
// the borders are drawn with segments for their size on screen too (4 to 64).
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "app/document/document.hpp"
#include "app/editor/logic/live_curves.hpp"
#include "app/editor/logic/live_surfaces.hpp"
#include "app/editor/logic/net_thinning.hpp"
#include "app/editor/logic/view_copy.hpp"
#include "core/eval/density_choice.hpp"
#include "render/display_settings.hpp"

namespace pl {

struct ViewBudgets {
  std::size_t fine_triangles = 600000;    // drawn at rest
  std::size_t coarse_triangles = 120000;  // drawn while dragging: the frame rate's share
};

// What a view evaluates, GL-free: built on a worker thread while the window shows a progress
// bar, then handed to EvaluatedView on the thread that owns the GL context.
struct ViewEvaluation {
  std::optional<FaceScheme> scheme;
  DensityBudget fine_budget, coarse_budget;
  std::unique_ptr<LiveSurfaces> coarse, fine;
  std::unique_ptr<LiveCurves> curves;
  uint64_t revision = 0;
};

struct ViewRequest {
  std::optional<FaceScheme> scheme;  // none: the scene's own
  int coarse_density = 16, fine_density = 48;
  bool combs = false;
  int comb_teeth = DisplaySettings().comb_teeth;
  ViewBudgets budgets;
};

// Called with the fraction of the work done (0 to 1) and what is being done.
using ViewProgress = std::function<void(double fraction, const char* stage)>;

// Evaluates `scene` (document revision `revision`, named `source` in messages) for a view:
// fills the network, evaluates every surface at both densities and samples the borders.
// Throws DataError when the scene cannot be evaluated.
ViewEvaluation evaluate_view(const Scene& scene, uint64_t revision, const std::string& source,
                             const ViewRequest& request, const ViewProgress& progress = {});

class EvaluatedView {
 public:
  // Takes an evaluation and gives it to its drawn copies, made by `copies` (on the GL thread
  // when they are GPU copies).
  EvaluatedView(ViewEvaluation evaluation, const ViewCopyFactory& copies);
  // Evaluates at once. Throws DataError when the scene cannot be evaluated.
  EvaluatedView(const Document& doc, const ViewRequest& request,
                const ViewCopyFactory& copies = {});

  // Follows the document; returns true when what is drawn changed. Throws DataError when the
  // edited network cannot be filled (the view keeps its last state).
  bool follow(const Document& doc);

  // Chooses every surface's density from its diameter on screen (`pixels(centre, radius)`: the
  // diameter in pixels of that sphere) within the budgets, and re-evaluates the surfaces whose
  // density changes (nothing while a drag is under way: its frames keep their cost). Returns
  // true when what is drawn changed. Cheap when nothing changes: one bounding sphere per surface.
  bool fit_to_screen(const std::function<double(const Vec3& centre, double radius)>& pixels,
                     const Document& doc);
  // "face densities 6-24, 412 k of 600 k triangles": for the status bar.
  std::string density_note() const;
  // For the status bar, when drawing is the limit: the face densities when some face is drawn
  // below the highest density, and what the control net's thinning hides; empty otherwise.
  std::string drawing_note() const;

  // Which control points are drawn and picked: those readable at their size on screen (from
  // the last fit_to_screen; net_thinning.hpp) and, whatever their size, those of `focus`.
  // point_px: a drawn point's width in pixels. Uploads the net when it or the points changed;
  // cheap otherwise.
  void show_net(const NetFocus& focus, double point_px, const Document& doc);
  // What show_net hides, for the status bar; empty when nothing is.
  std::string net_note() const { return thinning_.note(); }

  // Curvature combs on or off and their tooth count: applied by the next follow(), which
  // resamples the curves of the surfaces shown without re-evaluating them (no comb work while
  // combs are off).
  void configure_combs(bool combs, int teeth) { curves_->configure(combs, teeth); }

  const LiveSurfaces& shown() const { return coarse_shown_ ? *coarse_ : *fine_; }
  const ViewCopy& copy() const { return coarse_shown_ ? *copy_coarse_ : *copy_fine_; }
  const LiveSurfaces& fine() const { return *fine_; }
  const LiveSurfaces& coarse() const { return *coarse_; }
  const LiveCurves& curves() const { return *curves_; }
  bool settled() const { return !coarse_shown_; }
  std::optional<FaceScheme> scheme() const { return scheme_; }
  double last_eval_ms() const { return last_eval_ms_; }

 private:
  // Brings the curves up to `live` (last synced from revision `from`, changing `changed`) and
  // gives them to `copy` if it is older. Returns true when it did.
  bool follow_curves(const Document& doc, const LiveSurfaces& live, uint64_t from,
                     const std::vector<int>& changed, ViewCopy& copy, uint64_t& copy_serial);

  // The border polylines uploaded: LiveCurves' own, or every k-th point of one (a border a few
  // pixels long on screen needs a few segments, not 64).
  std::vector<const CurvatureComb*> drawn_borders();
  // Gives the shown points of `live` to `copy` unless `key` says it holds them already.
  void upload_net(const LiveSurfaces& live, ViewCopy& copy, uint64_t& key);

  std::optional<FaceScheme> scheme_;
  DensityBudget fine_budget_, coarse_budget_;
  // Whether each view's densities were chosen from sizes on screen yet (they start uniform).
  bool fine_fitted_ = false, coarse_fitted_ = false;
  std::vector<int> border_segments_;  // per surface, from the last fit_to_screen
  std::vector<CurvatureComb> thin_borders_;
  std::unique_ptr<LiveSurfaces> coarse_, fine_;
  std::unique_ptr<LiveCurves> curves_;
  std::unique_ptr<ViewCopy> copy_fine_, copy_coarse_;
  uint64_t fine_revision_, coarse_revision_;
  uint64_t fine_curves_serial_ = UINT64_MAX, coarse_curves_serial_ = UINT64_MAX;
  bool coarse_shown_ = false;
  double last_eval_ms_ = 0;
  // Control-net thinning: the sizes it used, what it was computed for, and the uploads.
  NetScreenSizes net_sizes_;
  uint64_t net_sizes_serial_ = 0, net_serial_ = 0;
  struct NetKey {
    const LiveSurfaces* live = nullptr;
    uint64_t layout = UINT64_MAX, sizes = UINT64_MAX;
    NetFocus focus;
    double point_px = 0;
    bool operator==(const NetKey&) const = default;
  } net_key_;
  NetThinning thinning_;
  uint64_t fine_net_key_ = UINT64_MAX, coarse_net_key_ = UINT64_MAX;
  ControlNet net_scratch_;
  std::vector<Arrow> arrows_scratch_;
};

}  // namespace pl
