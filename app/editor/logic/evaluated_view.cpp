#include "app/editor/logic/evaluated_view.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <tuple>

#include "render/draw_scene_builder.hpp"

namespace pl {

namespace {

std::string source_of(const Document& doc) {
  return doc.path().empty() ? std::string("scene") : doc.path().string();
}

// Sizes of the surfaces as they are evaluated; pixels from `pixels` when given.
// `fitted`: whether the densities were chosen from sizes on screen already (SurfaceSize).
std::vector<SurfaceSize> sizes_of(
    const LiveSurfaces& live, const std::function<double(const Vec3&, double)>* pixels = nullptr,
    bool fitted = true) {
  std::vector<SurfaceSize> sizes;
  for (const SceneSurface& s : live.surfaces().surfaces) {
    SurfaceSize z;
    z.triangles = s.evaluator->tessellation().triangles.size();
    z.density = s.evaluator->tessellation().density;
    z.fitted = fitted;
    if (pixels) {
      const Sphere sphere = bounding_sphere(s.evaluator->patch());
      z.pixels = (*pixels)(sphere.centre, sphere.radius);
    }
    sizes.push_back(z);
  }
  return sizes;
}

std::size_t triangles_of(const LiveSurfaces& live) {
  std::size_t t = 0;
  for (const SceneSurface& s : live.surfaces().surfaces)
    t += s.evaluator->tessellation().triangles.size();
  return t;
}

// Segments of a curve `pixels` long on screen: a power of two, a segment every ~6 pixels, 4 to 64
// (kCurveSegments: what LiveCurves and LiveSurfaces sample, so every count divides it).
int curve_segments(double pixels) {
  int s = 4;
  while (s < kCurveSegments && s * 6.0 < pixels) s *= 2;
  return s;
}

// Segments of a network edge (cubic Bezier control points cp, `scale` pixels per model unit at
// the edge): the fewest (a power of two, 2 to kCurveSegments; 2 so that the midpoint is a
// sample, where picking and scripts find a curve) whose polyline lies within a quarter pixel of
// the curve, in depth as across the screen. A polyline of n equal parameter steps is within
// |B''|max / (8 n^2) of the curve, and |B''| <= 6 max |P[i] - 2 P[i+1] + P[i+2]|. A gently
// curved edge needs a few segments however long it is on screen: a dense network's curves are
// drawn with a fraction of the segments a length rule gives, which is what a CPU rasteriser
// pays for.
int edge_segments(const Vec3 (&cp)[4], double scale) {
  const double bend = scale * std::max(glm::length(cp[0] - 2.0 * cp[1] + cp[2]),
                                       glm::length(cp[1] - 2.0 * cp[2] + cp[3]));
  const double tolerance = 0.25;
  int s = 2;
  while (s < kCurveSegments && 0.75 * bend > tolerance * s * s) s *= 2;
  return s;
}

// The highest density of the budget's chain at which `live`'s surfaces fit it.
int start_density(const LiveSurfaces& live, const DensityBudget& budget) {
  return uniform_density(sizes_of(live), budget);
}

}  // namespace

ViewEvaluation evaluate_view(const Scene& scene, uint64_t revision, const std::string& source,
                             const ViewRequest& r, const ViewProgress& progress) {
  auto report = [&](double f, const char* stage) {
    if (progress) progress(f, stage);
  };
  ViewEvaluation v;
  v.scheme = r.scheme;
  v.revision = revision;
  // A sample every 8 pixels at rest: the triangles a dense network's faces need (a sphere's
  // chords are then far below a pixel from it), not four times as many from rounding 6 up.
  v.fine_budget = {2, r.fine_density, 8, r.budgets.fine_triangles};
  // The coarse view samples as many times less densely as the densities' ratio: a sample every
  // 24 pixels with the default densities, so a dense network's faces (a few dozen pixels wide)
  // are drawn at the chain's lowest level while dragging, where the triangles' count is the
  // frame's cost on a CPU rasteriser (its chain starts at the coarse density).
  v.coarse_budget = {2, r.coarse_density, 8.0 * r.fine_density / std::max(1, r.coarse_density),
                     r.budgets.coarse_triangles};
  // Both start at the lowest density, which costs the filling alone, and are then refined to
  // the density that fits their budget: a big network never holds more samples than that.
  report(0.0, "filling the network");
  const int first = std::min(2, r.coarse_density);
  v.coarse = std::make_unique<LiveSurfaces>(scene, first, r.scheme, source, revision);
  const std::size_t n = v.coarse->surfaces().surfaces.size();
  report(0.25, "evaluating the drag surfaces");
  const int coarse_start = start_density(*v.coarse, v.coarse_budget);
  if (coarse_start != first) v.coarse->set_densities(std::vector<int>(n, coarse_start));
  // At rest a drag's release moves points once: the fine view keeps no jets.
  report(0.3, "filling the network");
  const int fine_start = start_density(*v.coarse, v.fine_budget);
  v.fine = std::make_unique<LiveSurfaces>(scene, std::min(first, fine_start), r.scheme, source,
                                          revision, SampleStorage::Compact);
  // The fine surfaces in slices, so that the progress moves.
  std::vector<int> densities = v.fine->densities();
  constexpr std::size_t kSlices = 16;
  for (std::size_t k = 0; k < kSlices; ++k) {
    report(0.5 + 0.45 * double(k) / kSlices, "evaluating the surfaces");
    for (std::size_t i = n * k / kSlices; i < n * (k + 1) / kSlices && i < densities.size(); ++i)
      densities[i] = fine_start;
    v.fine->set_densities(densities);
  }
  report(0.95, "sampling the borders");
  v.curves = std::make_unique<LiveCurves>(r.combs, r.comb_teeth);
  v.curves->follow(scene, v.fine->surfaces(), revision, revision, {},
                   &v.fine->evaluation().filling().topology());
  report(1.0, "done");
  return v;
}

EvaluatedView::EvaluatedView(const Document& doc, const ViewRequest& request,
                             const ViewCopyFactory& copies)
    : EvaluatedView(evaluate_view(doc.scene(), doc.revision(), source_of(doc), request), copies) {}

EvaluatedView::EvaluatedView(ViewEvaluation v, const ViewCopyFactory& copies)
    : scheme_(v.scheme), curves_(std::move(v.curves)) {
  for (auto [d, live, budget] : {std::tuple(&fine_, &v.fine, v.fine_budget),
                                 std::tuple(&coarse_, &v.coarse, v.coarse_budget)}) {
    d->live = std::move(*live);
    d->copy = make_view_copy(copies);
    d->budget = budget;
    d->revision = v.revision;
    d->copy->update_meshes_and_curves(d->live->draw());
  }
  upload_net(fine_);
  // The curves are at the evaluation's revision already: give them to the fine copy.
  fine_.curves.require(curves_->serial());
  fine_.copy->update_curves(curves_->network_comb_refs(), drawn_borders(),
                            curves_->border_on_network(), curves_->free_comb_refs());
}

bool EvaluatedView::follow_curves(const Document& doc, Density& d, uint64_t from,
                                  const std::vector<int>& changed) {
  const LiveSurfaces& live = *d.live;
  curves_->follow(doc.scene(), live.surfaces(), from, live.synced_revision(), changed,
                  &live.evaluation().filling().topology());
  if (!d.curves.require(curves_->serial())) return false;
  d.copy->update_curves(curves_->network_comb_refs(), drawn_borders(), curves_->border_on_network(),
                        curves_->free_comb_refs());
  return true;
}

std::vector<const CurvatureComb*> EvaluatedView::drawn_borders() {
  const auto& borders = curves_->borders();
  if (border_segments_.size() != borders.size()) return curves_->border_refs();
  thin_borders_.clear();
  std::size_t count = 0;
  for (const auto& surface : borders) count += surface.size();
  thin_borders_.reserve(count);  // pointers into it stay valid
  std::vector<const CurvatureComb*> refs;
  for (std::size_t i = 0; i < borders.size(); ++i)
    for (const CurvatureComb& c : borders[i]) {
      const int segments = border_segments_[i];
      if (!c.teeth.empty() || c.points.size() != std::size_t(kCurveSegments) + 1 ||
          segments >= kCurveSegments) {
        refs.push_back(&c);
        continue;
      }
      CurvatureComb& thin = thin_borders_.emplace_back();
      for (int k = 0; k <= kCurveSegments; k += kCurveSegments / segments)
        thin.points.push_back(c.points[k]);
      refs.push_back(&thin);
    }
  return refs;
}

namespace {
// The live surfaces brought up to the document, told what changed when the document knows.
std::vector<int> sync_live(LiveSurfaces& live, const Document& doc) {
  const auto faces = doc.interior_faces_since(live.synced_revision());
  if (!faces) return live.sync(doc.scene(), doc.revision());
  const InteriorEdit known{*faces};
  return live.sync(doc.scene(), doc.revision(), &known);
}
}  // namespace

bool EvaluatedView::follow(const Document& doc) {
  // While a drag is under way the coarse density follows and is drawn; at rest the fine one.
  const bool dragging = doc.dragging();
  const bool switched = coarse_shown_ != dragging;
  coarse_shown_ = dragging;
  return follow_density(doc, dragging ? coarse_ : fine_, switched);
}

bool EvaluatedView::follow_density(const Document& doc, Density& d, bool switched) {
  if (d.revision == doc.revision())
    return follow_curves(doc, d, d.live->synced_revision(), {}) || switched;
  d.revision = doc.revision();  // first: a failing sync is not retried every frame
  const uint64_t from = d.live->synced_revision();
  const std::vector<int> changed = sync_live(*d.live, doc);
  last_eval_ms_ = d.live->last_sync_ms();
  d.copy->update_meshes_and_curves(d.live->draw());
  follow_curves(doc, d, from, changed);
  return true;
}

bool EvaluatedView::fit_to_screen(
    const std::function<double(const Vec3& centre, double radius)>& pixels, const Document& doc) {
  if (doc.dragging() || fine_.revision != doc.revision()) return false;
  bool drawn_changed = !fine_.live
                            ->set_densities(choose_densities(
                                sizes_of(*fine_.live, &pixels, fine_.fitted), fine_.budget))
                            .empty();
  fine_.fitted = true;
  // The coarse view only when it shows the same surfaces (it catches up when a drag starts).
  const bool coarse_current = coarse_.revision == doc.revision();
  bool coarse_changed =
      coarse_current && !coarse_.live
                             ->set_densities(choose_densities(
                                 sizes_of(*coarse_.live, &pixels, coarse_.fitted), coarse_.budget))
                             .empty();
  coarse_.fitted |= coarse_current;
  // Curves: network edges by their own size on screen, borders by their surface's.
  std::vector<double> edge_pixels;
  if (doc.scene().network) {
    std::vector<int> segments;
    const Network& net = *doc.scene().network;
    for (std::size_t e = 0; e < net.edges.size(); ++e) {
      const auto& ed = net.edges[e];
      const Vec3 cp[4] = {net.vertices[ed.v[0]], ed.handles[0], ed.handles[1],
                          net.vertices[ed.v[1]]};
      const Vec3 centre = (cp[0] + cp[1] + cp[2] + cp[3]) / 4.0;
      double radius = 0;
      for (const Vec3& p : cp) radius = std::max(radius, glm::length(p - centre));
      edge_pixels.push_back(pixels(centre, radius));
      segments.push_back(edge_segments(cp, radius > 0 ? edge_pixels.back() / (2 * radius) : 0));
    }
    if (fine_.live->set_curve_segments(segments)) drawn_changed = true;
    if (coarse_current) coarse_changed |= coarse_.live->set_curve_segments(segments);
  }
  std::vector<int> borders;
  for (const SceneSurface& s : fine_.live->surfaces().surfaces) {
    const Sphere sphere = bounding_sphere(s.evaluator->patch());
    borders.push_back(curve_segments(pixels(sphere.centre, sphere.radius)));
  }
  if (borders != border_segments_) {
    border_segments_ = std::move(borders);
    fine_.curves.invalidate();  // given to the copies again, thinned anew
    coarse_.curves.invalidate();
    drawn_changed |= follow_curves(doc, fine_, fine_.live->synced_revision(), {});
  }
  if (drawn_changed) fine_.copy->update_meshes_and_curves(fine_.live->draw());
  if (coarse_changed) coarse_.copy->update_meshes_and_curves(coarse_.live->draw());
  // The sizes the control net is thinned for: each edge's and each surface's on screen.
  NetScreenSizes sizes;
  sizes.edge_pixels = std::move(edge_pixels);
  for (const SceneSurface& s : fine_.live->surfaces().surfaces) {
    const Sphere sphere = bounding_sphere(s.evaluator->patch());
    sizes.surface_pixels.push_back(pixels(sphere.centre, sphere.radius));
  }
  // A small zoom keeps the thinning when no object crosses its threshold ... so compare the
  // decisions, not the sizes: thinning is recomputed when any size moved by 10 %.
  auto moved = [](const std::vector<double>& a, const std::vector<double>& b) {
    if (a.size() != b.size()) return true;
    for (std::size_t i = 0; i < a.size(); ++i)
      if (std::abs(a[i] - b[i]) > 0.1 * std::max(a[i], b[i])) return true;
    return false;
  };
  if (moved(sizes.edge_pixels, net_sizes_.edge_pixels) ||
      moved(sizes.surface_pixels, net_sizes_.surface_pixels)) {
    net_sizes_ = std::move(sizes);
    ++net_sizes_serial_;
  }
  return drawn_changed;
}

void EvaluatedView::show_net(const NetFocus& focus, double point_px, const Document& doc) {
  Density& d = shown_density();
  LiveSurfaces& live = *d.live;
  if (thinning_key_.require({&live, live.points_layout(), net_sizes_serial_, focus, point_px})) {
    thinning_ = thin_control_net(live.points(), live.surfaces(),
                                 doc.scene().network ? &*doc.scene().network : nullptr, net_sizes_,
                                 focus, point_px);
    live.set_hidden_points(thinning_.hidden);
    ++net_serial_;
  }
  upload_net(d);
}

void EvaluatedView::upload_net(Density& d) {
  // The points move with every sync (revision) and the hidden ones with every thinning.
  const LiveSurfaces& live = *d.live;
  if (!d.net.require({live.synced_revision(), net_serial_, live.points_layout()})) return;
  const ScenePoints& pts = live.points();
  make_control_net(pts, true, net_scratch_);
  arrows_scratch_.clear();
  for (std::size_t a = 0; a < pts.arrows.size(); ++a)
    if (pts.shown(pts.arrow_base[a])) arrows_scratch_.push_back(pts.arrows[a]);
  d.copy->set_net(net_scratch_, arrows_scratch_);
}

std::string EvaluatedView::density_note() const {
  const std::vector<int> d = fine_.live->densities();
  if (d.empty()) return {};
  const auto [lo, hi] = std::minmax_element(d.begin(), d.end());
  char buf[160];
  std::snprintf(buf, sizeof buf, "face densities %d-%d, %zu k of %zu k triangles", *lo, *hi,
                triangles_of(*fine_.live) / 1000, fine_.budget.triangles / 1000);
  return buf;
}

std::string EvaluatedView::drawing_note() const {
  const std::vector<int> d = fine_.live->densities();
  std::string note;
  if (std::any_of(d.begin(), d.end(), [&](int x) { return x < fine_.budget.max_density; })) {
    const auto [lo, hi] = std::minmax_element(d.begin(), d.end());
    char buf[160];
    std::snprintf(buf, sizeof buf, "densities %d-%d for size on screen (%zu k of %zu k triangles)",
                  *lo, *hi, triangles_of(*fine_.live) / 1000, fine_.budget.triangles / 1000);
    note = buf;
  }
  const std::string net = net_note();
  if (!net.empty()) note += (note.empty() ? "" : "; ") + net;
  return note;
}

}  // namespace pl
