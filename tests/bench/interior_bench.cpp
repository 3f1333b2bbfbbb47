// Interior control of a network GB face: one free point of a degree-6 pentagon face dragged
// through the engine (SceneEvaluation::sync of the scene with that point's offset changed: the
// face's samples and normals updated by the point's influence column) against the full
// re-evaluation of that face (every sample of its patch evaluated again, with normals and
// curvatures) and against the refill the engine would otherwise do (the face's patch built
// again, then evaluated). Measured in the same run at the editor's densities (16 while dragging,
// 48 at rest) and at ~100k samples, with the one-off influence column build at drag start.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

#include "bench_common.hpp"
#include "bench_scenes.hpp"
#include "core/eval/scene_evaluation.hpp"
#include "core/network/gb_face.hpp"
#include "core/network/gb_face_interior.hpp"

namespace pl::bench {

namespace {

// A pentagon face on a gently curved loop, degree 6, its centre and one inner-row point moved.
Scene pentagon_scene() {
  Scene scene = wavy_ring_face(5, 0.15, 2, 0.08);
  NetworkFace& face = scene.network->faces[0];
  face.degree = 6;
  face.offsets = {{.centre = true, .by = {0, 0, 0.2}},
                  {.side = 2, .j = 2, .layer = 2, .by = {0, 0, 0.1}}};
  return scene;
}

}  // namespace

void bench_interior(const Options& o) {
  Scene scene = pentagon_scene();
  for (int density : {16, 48, 224}) {
    if (o.quick && density > 16) break;
    SceneEvaluation ev(scene, density, std::nullopt, "bench");
    const PatchEvaluator& face = *ev.surfaces().surfaces.at(0).evaluator;
    // The dragged point: [1, 3, 2], the middle of side 1's layer 2 (not yet offset).
    NetworkFace& f = scene.network->faces[0];
    f.offsets.push_back({.side = 1, .j = 3, .layer = 2, .by = {0, 0, 0}});
    Vec3& by = f.offsets.back().by;
    int step = 0;
    const auto drag = [&] {
      by.z += (++step % 2 ? 1e-3 : -1e-3);
      ev.sync(scene);
    };
    drag();  // the one-off column build at drag start
    const double drag_ms = median_ms(o.quick ? 3 : 60, drag);
    // The full re-evaluation of that face: its patch evaluated at every sample again.
    PatchEvaluator full(std::shared_ptr<Patch>(face.patch().clone()),
                        ev.cache().get(face.patch().domain(), density));
    const double full_ms = median_ms(o.quick ? 2 : 15, [&] { full.evaluate_all(); });
    // The one-off cost at drag start: the dragged point's influence column (evaluate_all drops
    // the cached columns first, untimed).
    const std::size_t k = interior_point_index(5, 6, {.side = 1, .j = 3, .layer = 2});
    std::vector<double> columns;
    for (int r = 0; r < (o.quick ? 2 : 9); ++r) {
      full.evaluate_all();
      const auto a = std::chrono::steady_clock::now();
      full.prepare_influence(k);
      columns.push_back(
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - a).count());
    }
    std::nth_element(columns.begin(), columns.begin() + columns.size() / 2, columns.end());
    const double column_ms = columns[columns.size() / 2];
    // The refill: the face's patch built from its ribbons, then evaluated.
    const double refill_ms = median_ms(o.quick ? 2 : 15, [&] {
      PatchEvaluator e(std::shared_ptr<Patch>(ev.filling().build(0).patch),
                       ev.cache().get(face.patch().domain(), density));
    });
    const std::string tag = density == 224 ? "_100k" : "_d" + std::to_string(density);
    figure(("interior_drag_ms" + tag).c_str(), drag_ms, "ms");
    figure(("interior_face_full_eval_ms" + tag).c_str(), full_ms, "ms");
    figure(("interior_face_refill_ms" + tag).c_str(), refill_ms, "ms");
    figure(("interior_drag_speedup" + tag).c_str(), full_ms / drag_ms, "x");
    figure(("interior_drag_column_ms" + tag).c_str(), column_ms, "ms");
    figure(("interior_samples" + tag).c_str(), double(face.sample_count()), "samples");
    if (density == 48) {  // the editor's density at rest: the figures under their plain names
      figure("interior_drag_ms", drag_ms, "ms");
      figure("interior_face_full_eval_ms", full_ms, "ms");
    }
    f.offsets.pop_back();
  }
}

}  // namespace pl::bench
