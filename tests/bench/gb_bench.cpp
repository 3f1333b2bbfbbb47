// GB figures: full evaluation of cagd86 (5 sides, degree 5) with second
// derivatives, normals and curvatures, and of a network GB face of 5 sides and degree 5; the drag
// update at ~1e5 samples with its influence column prepared; the one-off column build at ~1e6
// samples. The evaluation and the drag are measured with one core held busy by another process too
// (*_busy, and their ratios to the quiet figures).
#include <chrono>
#include <cmath>
#include <filesystem>

#include "bench_common.hpp"
#include "bench_patches.hpp"
#include "bench_scenes.hpp"
#include "core/base/parallel_for.hpp"
#include "core/domain/tessellation_cache.hpp"
#include "core/eval/patch_evaluator.hpp"
#include "core/eval/scene_surfaces.hpp"
#include "core/io/gbp_io.hpp"
#include "core/patch/gb/shared_basis.hpp"

namespace pl::bench {

// The reference model cagd86 (5 sides, degree 5) from the repository's test data.
std::shared_ptr<GBPatch> cagd86() {
  const auto file = std::filesystem::path(PATCHLAB_TEST_DATA_DIR) / "gb" / "cagd86.gbp";
  return std::make_shared<GBPatch>(read_gbp(file));  // throws (the program fails) if it is missing
}

namespace {

// density N of the regular pentagon gives 1 + 5 N (N + 1) / 2 samples.
std::shared_ptr<const Tessellation> pentagon(int density) {
  return std::make_shared<const Tessellation>(ConvexPolygonDomain::regular(5).tessellate(density));
}

}  // namespace

void bench_gb(const Options& o) {
  const auto patch = cagd86();
  {
    PatchEvaluator ev(patch, pentagon(o.quick ? 60 : 632));  // 1,000,141 samples
    const QuietBusy t =
        median_ms_quiet_busy(o.quick ? 2 : 8, o.quick ? 1 : 4, [&] { ev.evaluate_all(); });
    const double ms = t.quiet, samples = double(ev.sample_count());
    figures_quiet_busy("gb_full_eval_msamples_per_s", "Msamples/s", samples / (t.quiet * 1e3),
                       samples / (t.busy * 1e3), "gb_full_eval_busy_over_quiet");
    // The same work one sample at a time (evaluate, differential_geometry), as evaluate_all did
    // before the batched paths: the baseline of the speed-up, in the same run.
    const auto& xs = ev.tessellation().points;
    std::vector<SurfaceJet> jets(xs.size());
    std::vector<SurfaceGeometry> geometry(xs.size());
    const double scalar_ms = median_ms(o.quick ? 2 : 3, [&] {
      parallel_chunks(xs.size(), ev.grains().evaluate, [&](std::size_t b, std::size_t e) {
        for (std::size_t i = b; i < e; ++i) {
          jets[i] = patch->evaluate(xs[i]);
          geometry[i] = differential_geometry(jets[i]);
        }
      });
    });
    figure("gb_full_eval_scalar_msamples_per_s", ev.sample_count() / (scalar_ms * 1e3),
           "Msamples/s");
    figure("gb_full_eval_speedup_over_scalar", scalar_ms / ms, "x");
    // A network GB face of the same side count and degree (one pentagon on a wavy circle,
    // degree 5 with its centre raised: a gb-ribbons patch with interior control) over the same
    // pentagon at the same density, in the same run: one face on its own, its basis not shared.
    {
      Scene scene = wavy_ring_face(5, 0.1, 3, 0.05);
      NetworkFace& face = scene.network->faces[0];
      face.scheme = FaceScheme::GB;
      face.degree = 5;
      face.offsets.push_back({.centre = true, .by = Vec3(0, 0, 0.05)});
      TessellationCache cache;
      const SceneSurfaces s = evaluate_scene(scene, 2, std::nullopt, cache, "bench");
      PatchEvaluator face_ev(std::shared_ptr<Patch>(s.surfaces.at(0).evaluator->patch().clone()),
                             pentagon(o.quick ? 60 : 632));
      const SharedBasisBypass alone;  // no basis kept from another face: this face's own work
      const double face_ms = median_ms(o.quick ? 2 : 5, [&] { face_ev.evaluate_all(); });
      const double face_rate = face_ev.sample_count() / (face_ms * 1e3);
      figure("gb_network_face_msamples_per_s", face_rate, "Msamples/s");
      figure("gb_network_face_over_gb_full_eval", face_rate / (samples / (t.quiet * 1e3)), "x");
    }
    if (cpu_has_wide_lanes()) {  // what a CPU with AVX2 but without AVX-512 runs
      narrow_lanes_only = true;
      const double narrow_ms = median_ms(o.quick ? 2 : 5, [&] { ev.evaluate_all(); });
      narrow_lanes_only = false;
      figure("gb_full_eval_narrow_lanes_msamples_per_s", ev.sample_count() / (narrow_ms * 1e3),
             "Msamples/s");
    }
  }
  // An inner point of layer 1: it moves most of the patch.
  const std::size_t k = patch->index(1, 2, 1);
  {
    PatchEvaluator ev(std::shared_ptr<Patch>(patch->clone()), pentagon(o.quick ? 30 : 200));
    ev.prepare_influence(k);  // 100,501 samples
    Vec3 p = ev.patch().control_point(k);
    int step = 0;
    const QuietBusy t = median_ms_quiet_busy(o.quick ? 3 : 60, o.quick ? 1 : 6, [&] {
      p.z += (++step % 2 ? 1e-3 : -1e-3);
      ev.move_control_point(k, p);
    });
    figures_quiet_busy("gb_drag_ms_100k", "ms", t.quiet, t.busy, "gb_drag_busy_over_quiet_100k");
  }
  {
    PatchEvaluator ev(std::shared_ptr<Patch>(patch->clone()), pentagon(o.quick ? 60 : 632));
    std::vector<double> t;
    for (int r = 0; r < (o.quick ? 2 : 9); ++r) {
      ev.evaluate_all();  // drops the cached columns
      const auto a = std::chrono::steady_clock::now();
      ev.prepare_influence(k);
      const auto b = std::chrono::steady_clock::now();
      t.push_back(std::chrono::duration<double, std::milli>(b - a).count());
    }
    std::nth_element(t.begin(), t.begin() + t.size() / 2, t.end());
    figure("gb_drag_column_ms_1m", t[t.size() / 2], "ms");
  }
}

}  // namespace pl::bench
