// Figures of the foundation issue: full evaluation of a bicubic patch, and the incremental drag
// update compared with the streaming floor of the same bytes, in the same run.
#include <random>

#include "bench_common.hpp"
#include "core/domain/unit_square.hpp"
#include "core/eval/patch_evaluator.hpp"
#include "core/patch/bezier_patch.hpp"

namespace pl::bench {

namespace {

std::shared_ptr<BezierPatch> random_bicubic() {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> z(-0.3, 0.3);
  std::vector<Vec3> p;
  for (int i = 0; i <= 3; ++i)
    for (int j = 0; j <= 3; ++j) p.emplace_back(i / 3.0, j / 3.0, z(rng));
  return std::make_shared<BezierPatch>(3, 3, std::move(p));
}

// The physical floor of a drag update: stream the same bytes the update reads (influence column
// and jets) and writes (jets and geometry), with the same threads, doing no arithmetic of note.
double floor_ms(std::size_t n, int repeats) {
  std::vector<Jet> column(n, Jet(1e-9));
  std::vector<SurfaceJet> jets(n);
  std::vector<SurfaceGeometry> geometry(n);
  const std::ptrdiff_t m = static_cast<std::ptrdiff_t>(n);
  return median_ms(repeats, [&] {
#pragma omp parallel for schedule(static)
    for (std::ptrdiff_t i = 0; i < m; ++i) {
      SurfaceJet j = jets[i];
      j.p.x += column[i].f;
      j.svv.z += column[i].fvv;
      jets[i] = j;
      geometry[i].normal = j.su;
      geometry[i].gaussian = j.suv.x;
      geometry[i].mean = j.suv.y;
      geometry[i].kmin = j.p.x;
      geometry[i].kmax = j.p.y;
    }
  });
}

void drag_figures(int density, const char* suffix, int repeats) {
  UnitSquareDomain square;
  auto tess = std::make_shared<const Tessellation>(square.tessellate(density));
  PatchEvaluator ev(random_bicubic(), tess);
  const std::size_t k = 5;  // an interior point: it influences every interior sample
  ev.prepare_influence(k);
  Vec3 p = ev.patch().control_point(k);
  int step = 0;
  const double update = median_ms(repeats, [&] {
    p.z += (++step % 2 ? 1e-3 : -1e-3);
    ev.move_control_point(k, p);
  });
  const double floor = floor_ms(ev.sample_count(), repeats);
  char name[64];
  std::snprintf(name, sizeof name, "drag_update_ms_%s", suffix);
  figure(name, update, "ms");
  std::snprintf(name, sizeof name, "drag_floor_ms_%s", suffix);
  figure(name, floor, "ms");
  std::snprintf(name, sizeof name, "drag_update_over_floor_%s", suffix);
  figure(name, update / floor, "x");
}

}  // namespace

void bench_bezier(const Options& o) {
  {
    const int density = o.quick ? 60 : 999;  // (N+1)^2 = 1e6 samples
    UnitSquareDomain square;
    auto tess = std::make_shared<const Tessellation>(square.tessellate(density));
    PatchEvaluator ev(random_bicubic(), tess);
    const double ms = median_ms(o.quick ? 2 : 7, [&] { ev.evaluate_all(); });
    figure("full_eval_msamples_per_s", ev.sample_count() / (ms * 1e3), "Msamples/s");
  }
  drag_figures(o.quick ? 30 : 315, "100k", o.quick ? 3 : 41);  // 316^2 = 99856 samples
  drag_figures(o.quick ? 60 : 999, "1m", o.quick ? 3 : 21);
}

}  // namespace pl::bench
