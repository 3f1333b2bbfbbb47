#include "app/editor/evaluated_view.hpp"

namespace pl {

namespace {
std::string source_of(const Document& doc) {
  return doc.path().empty() ? std::string("scene") : doc.path().string();
}
}  // namespace

EvaluatedView::EvaluatedView(const Document& doc, std::optional<FaceScheme> scheme,
                             int coarse_density, int fine_density, bool combs, int comb_teeth)
    : scheme_(scheme),
      fine_(doc.scene(), fine_density, scheme, source_of(doc), doc.revision()),
      coarse_(doc.scene(), coarse_density, scheme, source_of(doc), doc.revision()),
      curves_(combs, comb_teeth),
      gpu_fine_(fine_.draw()),
      gpu_coarse_(coarse_.draw()),
      fine_revision_(doc.revision()),
      coarse_revision_(doc.revision()) {
  follow_curves(doc, fine_, doc.revision(), {}, gpu_fine_, fine_curves_serial_);
}

bool EvaluatedView::follow_curves(const Document& doc, const LiveSurfaces& live, uint64_t from,
                                  const std::vector<int>& changed, GpuScene& gpu,
                                  uint64_t& gpu_serial) {
  curves_.follow(doc.scene(), live.surfaces(), from, live.synced_revision(), changed);
  if (gpu_serial == curves_.serial()) return false;
  gpu_serial = curves_.serial();
  gpu.update_curves(curves_.network_comb_refs(), curves_.border_refs(),
                    curves_.border_on_network());
  return true;
}

bool EvaluatedView::follow(const Document& doc) {
  if (doc.dragging()) {
    const bool was_fine = !coarse_shown_;
    coarse_shown_ = true;
    if (coarse_revision_ == doc.revision())
      return follow_curves(doc, coarse_, coarse_.synced_revision(), {}, gpu_coarse_,
                           coarse_curves_serial_) ||
             was_fine;
    coarse_revision_ = doc.revision();  // first: a failing sync is not retried every frame
    const uint64_t from = coarse_.synced_revision();
    const std::vector<int> changed = coarse_.sync(doc.scene(), doc.revision());
    last_eval_ms_ = coarse_.last_sync_ms();
    gpu_coarse_.update_geometry(coarse_.draw());
    follow_curves(doc, coarse_, from, changed, gpu_coarse_, coarse_curves_serial_);
    return true;
  }
  const bool was_coarse = coarse_shown_;
  coarse_shown_ = false;
  if (fine_revision_ == doc.revision())
    return follow_curves(doc, fine_, fine_.synced_revision(), {}, gpu_fine_, fine_curves_serial_) ||
           was_coarse;
  fine_revision_ = doc.revision();
  const uint64_t from = fine_.synced_revision();
  const std::vector<int> changed = fine_.sync(doc.scene(), doc.revision());
  last_eval_ms_ = fine_.last_sync_ms();
  gpu_fine_.update_geometry(fine_.draw());
  follow_curves(doc, fine_, from, changed, gpu_fine_, fine_curves_serial_);
  return true;
}

}  // namespace pl
