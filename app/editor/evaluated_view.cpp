#include "app/editor/evaluated_view.hpp"

namespace pl {

namespace {
std::string source_of(const Document& doc) {
  return doc.path().empty() ? std::string("scene") : doc.path().string();
}
}  // namespace

EvaluatedView::EvaluatedView(const Document& doc, std::optional<FaceScheme> scheme,
                             int coarse_density, int fine_density, int comb_teeth)
    : scheme_(scheme),
      fine_(doc.scene(), fine_density, scheme, source_of(doc), comb_teeth),
      coarse_(doc.scene(), coarse_density, scheme, source_of(doc), comb_teeth),
      gpu_fine_(fine_.draw()),
      gpu_coarse_(coarse_.draw()),
      fine_revision_(doc.revision()),
      coarse_revision_(doc.revision()) {}

bool EvaluatedView::follow(const Document& doc) {
  if (doc.dragging()) {
    const bool was_fine = !coarse_shown_;
    coarse_shown_ = true;
    if (coarse_revision_ == doc.revision()) return was_fine;
    coarse_revision_ = doc.revision();  // first: a failing sync is not retried every frame
    coarse_.sync(doc.scene(), doc.revision());
    last_eval_ms_ = coarse_.last_sync_ms();
    gpu_coarse_.update(coarse_.draw());
    return true;
  }
  const bool was_coarse = coarse_shown_;
  coarse_shown_ = false;
  if (fine_revision_ == doc.revision()) return was_coarse;
  fine_revision_ = doc.revision();
  fine_.sync(doc.scene(), doc.revision());
  last_eval_ms_ = fine_.last_sync_ms();
  gpu_fine_.update(fine_.draw());
  return true;
}

}  // namespace pl
