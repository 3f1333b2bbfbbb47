#include "app/editor/logic/scene_views.hpp"

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include "core/base/data_error.hpp"
#include "core/scene/network_edit.hpp"

namespace pl {

SceneViews::~SceneViews() {
  if (worker_.valid()) worker_.wait();
  for (auto& f : abandoned_) f.wait();
}

void SceneViews::rebuild(const Document& doc, const Preferences& prefs, bool compare,
                         std::chrono::milliseconds wait) {
  main_.reset();
  compare_views_.clear();
  error_.clear();
  compare_error_.clear();
  fields_.clear();
  difference_copies_.clear();
  range_.invalidate();
  compare_ = false;
  last_eval_ms_ = 0;  // the document before's; the worker's is taken in poll()
  if (worker_.valid()) abandoned_.push_back(std::move(worker_));  // its result is dropped
  std::erase_if(abandoned_, [](const std::future<void>& f) {
    return f.wait_for(std::chrono::seconds(0)) == std::future_status::ready;
  });
  auto job = std::make_shared<Job>();
  job->compare = compare && doc.scene().network.has_value();
  job->setup = compare_setup_from(prefs.compare_schemes, prefs.compare_base);
  job_ = job;
  const DisplaySettings& d = prefs.display;
  ViewRequest request;
  request.coarse_density = prefs.coarse_density;
  request.fine_density = prefs.fine_density;
  request.combs = d.combs;
  request.comb_teeth = d.comb_teeth;
  const std::string source = doc.path().empty() ? std::string("scene") : doc.path().string();
  // The worker owns a copy of the scene: the document may change meanwhile (follow() catches
  // up from the evaluated revision).
  worker_ = std::async(std::launch::async, [job, request, source, scene = doc.scene(),
                                            revision = doc.revision()]() mutable {
    std::vector<std::optional<FaceScheme>> schemes{std::nullopt};
    if (job->compare)
      for (FaceScheme s : job->setup.schemes) schemes.push_back(s);
    const std::size_t count = schemes.size();
    const auto t0 = std::chrono::steady_clock::now();
    try {
      for (std::size_t i = 0; i < count; ++i) {
        request.scheme = schemes[i];
        ViewEvaluation v =
            evaluate_view(scene, revision, source, request, [&](double f, const char* stage) {
              std::lock_guard lock(job->mutex);
              job->fraction = (double(i) + f) / double(count);
              job->stage = stage;
            });
        std::lock_guard lock(job->mutex);
        job->views.push_back(std::move(v));
        job->eval_ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                .count();
      }
    } catch (const std::exception& e) {
      std::lock_guard lock(job->mutex);
      // A pane whose scheme cannot fill the network (a ribbon scheme on a concave face) takes
      // the comparison away, not the scene's own view.
      const std::size_t failed = job->views.size();
      if (failed == 0)
        job->error = e.what();
      else
        job->pane_error = "pane " + std::to_string(failed) + " (" +
                          scheme_keyword(*schemes[failed]) + "): " + e.what();
    }
  });
  if (worker_.wait_for(wait) == std::future_status::ready) poll();
}

bool SceneViews::poll() {
  if (!job_ || !worker_.valid() ||
      worker_.wait_for(std::chrono::seconds(0)) != std::future_status::ready)
    return false;
  worker_.get();
  const std::shared_ptr<Job> job = std::move(job_);
  job_.reset();
  if (!job->error.empty() || job->views.empty()) {
    error_ = job->error.empty() ? "the scene could not be evaluated" : job->error;
    return true;
  }
  main_ = std::make_unique<EvaluatedView>(std::move(job->views[0]), copies_);
  last_eval_ms_ = job->eval_ms;
  compare_error_ = job->pane_error;
  if (job->compare && job->views.size() == job->setup.schemes.size() + 1) {
    for (std::size_t i = 1; i < job->views.size(); ++i)
      compare_views_.push_back(std::make_unique<EvaluatedView>(std::move(job->views[i]), copies_));
    setup_ = job->setup;
    fields_.resize(compare_views_.size());
    difference_copies_.resize(compare_views_.size());
    compare_ = true;
  }
  return true;
}

double SceneViews::load_fraction() const {
  if (!job_) return 1;
  std::lock_guard lock(job_->mutex);
  return job_->fraction;
}

std::string SceneViews::load_stage() const {
  if (!job_) return {};
  std::lock_guard lock(job_->mutex);
  return job_->stage;
}

bool SceneViews::follow(const Document& doc, const DisplaySettings& d) {
  const auto t0 = std::chrono::steady_clock::now();
  bool changed = false;
  // Combs turned on or off, or a new tooth count: the views resample their curves in follow()
  // (nothing is re-evaluated; no comb work while combs are off).
  auto follow_one = [&](EvaluatedView& v) {
    v.configure_combs(d.combs, d.comb_teeth);
    changed |= v.follow(doc);
  };
  // While comparing, the scene's own view is not shown: it is not followed either (leaving the
  // comparison evaluates afresh), so a drag frame costs one evaluation per pane.
  if (main_ && !compare_) follow_one(*main_);
  if (compare_)
    for (auto& v : compare_views_) follow_one(*v);
  if (changed)
    last_eval_ms_ =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return changed;
}

bool SceneViews::fit_to_screen(const std::function<double(const Vec3&, double)>& pixels,
                               const Document& doc) {
  bool changed = main_ && !compare_ && main_->fit_to_screen(pixels, doc);
  if (compare_)
    for (auto& v : compare_views_) changed |= v->fit_to_screen(pixels, doc);
  return changed;
}

void SceneViews::show_net(const NetFocus& focus, double point_px, const Document& doc) {
  if (main_ && !compare_) main_->show_net(focus, point_px, doc);
  if (compare_)
    for (auto& v : compare_views_) v->show_net(focus, point_px, doc);
}

const EvaluatedView& SceneViews::own(const Document& doc) {
  main_->follow(doc);
  return *main_;
}

bool SceneViews::settled() const {
  if (!main_ || (!compare_ && !main_->settled())) return false;
  for (const auto& v : compare_views_)
    if (!v->settled()) return false;
  return true;
}

const EvaluatedView& SceneViews::panel(int i) const {
  if (compare_ && i >= 0 && i < panels()) return *compare_views_[i];
  return *main_;
}

ColorRange SceneViews::colour_range(const DisplaySettings& d, uint64_t revision) {
  if (d.range) return *d.range;
  if (!main_ || d.base != BaseMode::Curvature) return range_value_;
  const RangeKey key{revision, settled(), panels(), d.curvature, d.range_percentile};
  if (!range_.require(key)) return range_value_;
  std::vector<const SurfaceMesh*> meshes;
  for (int i = 0; i < panels(); ++i)
    for (const SurfaceMesh& m : panel(i).shown().draw().surfaces) meshes.push_back(&m);
  range_value_ = automatic_range(meshes, d.curvature, d.range_percentile);
  return range_value_;
}

const ViewCopy* SceneViews::difference_scene(uint64_t revision, int panel) {
  if (!shows_distance(panel)) return nullptr;
  const EvaluatedView& base = *compare_views_[setup_.base_pane()];
  const EvaluatedView& view = *compare_views_[panel];
  const uint64_t key = revision * 2 + (view.settled() ? 1 : 0);
  if (fields_[panel].follow(base.shown().draw(), view.shown().draw(), key)) {
    if (!difference_copies_[panel]) difference_copies_[panel] = make_view_copy(copies_);
    difference_copies_[panel]->update(fields_[panel].scene());
  }
  return difference_copies_[panel].get();
}

void SceneViews::set_base(FaceScheme base) {
  if (std::find(setup_.schemes.begin(), setup_.schemes.end(), base) == setup_.schemes.end()) return;
  setup_.base = base;
  for (DifferenceField& f : fields_) f.reset();
}

double SceneViews::difference_max() const {
  double m = 0;
  for (int i = 0; i < int(fields_.size()); ++i)
    if (shows_distance(i)) m = std::max(m, fields_[i].max_abs());
  return m;
}

double SceneViews::difference_range() const {
  const double m = difference_max();
  return m > 0 ? m : 1e-12;
}

const DifferenceField* SceneViews::difference_field(int panel) const {
  return shows_distance(panel) ? &fields_[panel] : nullptr;
}

}  // namespace pl
