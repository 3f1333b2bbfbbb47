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
#include <tuple>

#include "app/document/document.hpp"
#include "app/editor/logic/live_curves.hpp"
#include "app/editor/logic/live_surfaces.hpp"
#include "app/editor/logic/net_thinning.hpp"
#include "app/editor/logic/view_copy.hpp"
#include "core/base/derived_from.hpp"
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

  const LiveSurfaces& shown() const { return *shown_density().live; }
  const ViewCopy& copy() const { return *shown_density().copy; }
  const LiveSurfaces& fine() const { return *fine_.live; }
  const LiveSurfaces& coarse() const { return *coarse_.live; }
  const LiveCurves& curves() const { return *curves_; }
  bool settled() const { return !coarse_shown_; }
  std::optional<FaceScheme> scheme() const { return scheme_; }
  double last_eval_ms() const { return last_eval_ms_; }

 private:
  // One density of the view: its live surfaces, their drawn copy and what the copy holds.
  struct Density {
    std::unique_ptr<LiveSurfaces> live;
    std::unique_ptr<ViewCopy> copy;
    DensityBudget budget;
    uint64_t revision = 0;         // the document revision last synced to (or tried)
    bool fitted = false;           // densities chosen from sizes on screen yet (they start uniform)
    DerivedFrom<uint64_t> curves;  // the copy's curves: of this LiveCurves serial
    // The copy's control net: of the points synced at this revision, thinned as the net serial
    // says, laid out as points_layout() says.
    DerivedFrom<std::tuple<uint64_t, uint64_t, uint64_t>> net;
  };
  const Density& shown_density() const { return coarse_shown_ ? coarse_ : fine_; }
  Density& shown_density() { return coarse_shown_ ? coarse_ : fine_; }

  // Brings the curves up to `d`'s surfaces (last synced from revision `from`, changing
  // `changed`) and gives them to its copy if it holds older ones. Returns true when it did.
  bool follow_curves(const Document& doc, Density& d, uint64_t from,
                     const std::vector<int>& changed);
  // Syncs `d` to the document; returns true when what it draws changed.
  bool follow_density(const Document& doc, Density& d, bool switched);

  // The border polylines uploaded: LiveCurves' own, or every k-th point of one (a border a few
  // pixels long on screen needs a few segments, not 64).
  std::vector<const CurvatureComb*> drawn_borders();
  // Gives the shown points of `d` to its copy unless it holds them already.
  void upload_net(Density& d);

  std::optional<FaceScheme> scheme_;
  Density fine_, coarse_;
  std::unique_ptr<LiveCurves> curves_;
  std::vector<int> border_segments_;  // per surface, from the last fit_to_screen
  std::vector<CurvatureComb> thin_borders_;
  bool coarse_shown_ = false;
  double last_eval_ms_ = 0;
  // Control-net thinning: the sizes it used (a serial moves when they do), what it was computed
  // for, and a serial that moves with each thinning.
  NetScreenSizes net_sizes_;
  uint64_t net_sizes_serial_ = 0, net_serial_ = 0;
  struct NetKey {
    const LiveSurfaces* live = nullptr;
    uint64_t layout = 0, sizes = 0;
    NetFocus focus;
    double point_px = 0;
    bool operator==(const NetKey&) const = default;
  };
  DerivedFrom<NetKey> thinning_key_;
  NetThinning thinning_;
  ControlNet net_scratch_;
  std::vector<Arrow> arrows_scratch_;
};

}  // namespace pl
