#include "app/editor/scene_views.hpp"

#include <chrono>

#include "core/base/data_error.hpp"

namespace pl {

void SceneViews::rebuild(const Document& doc, const Preferences& prefs, bool compare) {
  main_.reset();
  compare_views_[0].reset();
  compare_views_[1].reset();
  error_.clear();
  field_.reset();
  range_key_ = {};
  compare_ = false;
  try {
    const DisplaySettings& d = prefs.display;
    main_ = std::make_unique<EvaluatedView>(doc, std::nullopt, prefs.coarse_density,
                                            prefs.fine_density, d.combs, d.comb_teeth);
    if (compare && doc.scene().network) {
      compare_views_[0] =
          std::make_unique<EvaluatedView>(doc, FaceScheme::Gregory, prefs.coarse_density,
                                          prefs.fine_density, d.combs, d.comb_teeth);
      compare_views_[1] = std::make_unique<EvaluatedView>(
          doc, FaceScheme::GB, prefs.coarse_density, prefs.fine_density, d.combs, d.comb_teeth);
      compare_ = true;
    }
  } catch (const DataError& e) {
    error_ = e.what();
    main_.reset();
  }
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
