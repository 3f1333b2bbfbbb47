#include "app/editor/scene_views.hpp"

#include <chrono>
#include <stdexcept>

#include "core/base/data_error.hpp"

namespace pl {

SceneViews::~SceneViews() {
  if (worker_.valid()) worker_.wait();
  for (auto& f : abandoned_) f.wait();
}

void SceneViews::rebuild(const Document& doc, const Preferences& prefs, bool compare,
                         std::chrono::milliseconds wait) {
  main_.reset();
  compare_views_[0].reset();
  compare_views_[1].reset();
  error_.clear();
  field_.reset();
  difference_gpu_.reset();
  range_key_ = {};
  compare_ = false;
  if (worker_.valid()) abandoned_.push_back(std::move(worker_));  // its result is dropped
  std::erase_if(abandoned_, [](const std::future<void>& f) {
    return f.wait_for(std::chrono::seconds(0)) == std::future_status::ready;
  });
  auto job = std::make_shared<Job>();
  job->compare = compare && doc.scene().network.has_value();
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
    const std::size_t count = job->compare ? 3 : 1;
    const std::optional<FaceScheme> schemes[3] = {std::nullopt, FaceScheme::Gregory,
                                                  FaceScheme::GB};
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
      }
    } catch (const DataError& e) {
      std::lock_guard lock(job->mutex);
      job->error = e.what();
    } catch (const std::exception& e) {
      std::lock_guard lock(job->mutex);
      job->error = e.what();
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
  main_ = std::make_unique<EvaluatedView>(std::move(job->views[0]));
  if (job->compare && job->views.size() == 3) {
    compare_views_[0] = std::make_unique<EvaluatedView>(std::move(job->views[1]));
    compare_views_[1] = std::make_unique<EvaluatedView>(std::move(job->views[2]));
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
  if (main_) follow_one(*main_);
  if (compare_)
    for (auto& v : compare_views_) follow_one(*v);
  if (changed)
    last_eval_ms_ =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return changed;
}

bool SceneViews::fit_to_screen(const std::function<double(const Vec3&, double)>& pixels,
                               const Document& doc) {
  bool changed = main_ && main_->fit_to_screen(pixels, doc);
  if (compare_)
    for (auto& v : compare_views_) changed |= v->fit_to_screen(pixels, doc);
  return changed;
}

void SceneViews::show_net(const NetFocus& focus, double point_px, const Document& doc) {
  if (main_) main_->show_net(focus, point_px, doc);
  if (compare_)
    for (auto& v : compare_views_) v->show_net(focus, point_px, doc);
}

const EvaluatedView& SceneViews::panel(int i) const {
  if (compare_ && i >= 0 && i < 2) return *compare_views_[i];
  return *main_;
}

ColorRange SceneViews::colour_range(const DisplaySettings& d, uint64_t revision) {
  if (d.range) return *d.range;
  if (!main_ || d.base != BaseMode::Curvature) return range_;
  const RangeKey key{revision, settled(), compare_, d.curvature, d.range_percentile};
  if (key == range_key_) return range_;
  range_key_ = key;
  std::vector<const SurfaceMesh*> meshes;
  for (int i = 0; i < panels(); ++i)
    for (const SurfaceMesh& m : panel(i).shown().draw().surfaces) meshes.push_back(&m);
  range_ = automatic_range(meshes, d.curvature, d.range_percentile);
  return range_;
}

const GpuScene* SceneViews::difference_scene(uint64_t revision) {
  if (!compare_) return nullptr;
  const uint64_t key = revision * 2 + (compare_views_[1]->settled() ? 1 : 0);
  if (field_.follow(compare_views_[0]->shown().draw(), compare_views_[1]->shown().draw(), key)) {
    if (!difference_gpu_)
      difference_gpu_ = std::make_unique<GpuScene>(field_.scene());
    else
      difference_gpu_->update(field_.scene());
  }
  return difference_gpu_.get();
}

}  // namespace pl
