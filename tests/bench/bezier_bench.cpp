// Figures of the foundation issue: full evaluation of a bicubic patch, and the incremental drag
// update compared with the streaming floor of the same bytes, in the same run; each also with one
// core held busy by another process (the *_busy figures and their ratios to the quiet ones).
#include <random>

#include "bench_common.hpp"
#include "bench_patches.hpp"
#include "core/base/parallel_for.hpp"
#include "core/domain/unit_square.hpp"
#include "core/eval/patch_evaluator.hpp"
#include "core/patch/bezier_patch.hpp"

namespace pl::bench {

std::shared_ptr<BezierPatch> random_bicubic() {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> z(-0.3, 0.3);
  std::vector<Vec3> p;
  for (int i = 0; i <= 3; ++i)
    for (int j = 0; j <= 3; ++j) p.emplace_back(i / 3.0, j / 3.0, z(rng));
  return std::make_shared<BezierPatch>(3, 3, std::move(p));
}

namespace {

// The physical floor of a drag update: stream the same bytes the update reads (influence column
// and jets) and writes (jets and geometry), on the same scheduler with the same grain, doing no
// arithmetic of note.
struct Floor {
  std::vector<Jet> column;
  std::vector<SurfaceJet> jets;
  std::vector<SurfaceGeometry> geometry;
  std::size_t grain;
  Floor(std::size_t n, std::size_t grain)
      : column(n, Jet(1e-9)), jets(n), geometry(n), grain(grain) {}
  void operator()() {
    parallel_chunks(jets.size(), grain, [&](std::size_t b, std::size_t e) {
      for (std::size_t i = b; i < e; ++i) {
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
};

std::string name(const char* prefix, const char* suffix) {
  return std::string(prefix) + suffix;
}

void drag_figures(int density, const char* suffix, int repeats, int rounds) {
  UnitSquareDomain square;
  auto tess = std::make_shared<const Tessellation>(square.tessellate(density));
  PatchEvaluator ev(random_bicubic(), tess);
  const std::size_t k = 5;  // an interior point: it influences every interior sample
  ev.prepare_influence(k);
  Vec3 p = ev.patch().control_point(k);
  int step = 0;
  const QuietBusy update = median_ms_quiet_busy(repeats, rounds, [&] {
    p.z += (++step % 2 ? 1e-3 : -1e-3);
    ev.move_control_point(k, p);
  });
  Floor floor(ev.sample_count(), ev.grains().update);
  const QuietBusy floor_ms = median_ms_quiet_busy(repeats, rounds, floor);
  figures_quiet_busy(name("drag_update_ms_", suffix).c_str(), "ms", update.quiet, update.busy,
                     name("drag_update_busy_over_quiet_", suffix).c_str());
  figures_quiet_busy(name("drag_floor_ms_", suffix).c_str(), "ms", floor_ms.quiet, floor_ms.busy,
                     name("drag_floor_busy_over_quiet_", suffix).c_str());
  figure(name("drag_update_over_floor_", suffix).c_str(), update.quiet / floor_ms.quiet, "x");
  figure(name("drag_update_over_floor_", suffix).append("_busy").c_str(),
         update.busy / floor_ms.busy, "x");
}

}  // namespace

void bench_bezier(const Options& o) {
  {
    const int density = o.quick ? 60 : 999;  // (N+1)^2 = 1e6 samples
    UnitSquareDomain square;
    auto tess = std::make_shared<const Tessellation>(square.tessellate(density));
    PatchEvaluator ev(random_bicubic(), tess);
    const QuietBusy ms =
        median_ms_quiet_busy(o.quick ? 2 : 8, o.quick ? 1 : 4, [&] { ev.evaluate_all(); });
    const double samples = double(ev.sample_count());
    figures_quiet_busy("full_eval_msamples_per_s", "Msamples/s", samples / (ms.quiet * 1e3),
                       samples / (ms.busy * 1e3), "full_eval_busy_over_quiet");
  }
  drag_figures(o.quick ? 30 : 315, "100k", o.quick ? 3 : 60, o.quick ? 1 : 6);  // 99,856 samples
  drag_figures(o.quick ? 60 : 999, "1m", o.quick ? 3 : 24, o.quick ? 1 : 4);
}

}  // namespace pl::bench
