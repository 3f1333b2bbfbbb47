// `patchlab_bench --grains`: the sweep the evaluator's parallel grains were chosen from
// (PatchEvaluator::Grains). For each loop and grain, the median time quiet and with one core
// held busy by another process, in the same run:
//   grain_update_G_ms[_busy]    drag update of a bicubic patch, 99,856 samples
//   grain_evaluate_G_ms[_busy]  evaluate_all of the GB benchmark's patch, 100,501 samples
//   grain_column_G_ms[_busy]    an influence column's build on that GB patch
// A grain of the whole sample count runs on one thread (the sequential baseline).
#include "bench_common.hpp"
#include "bench_patches.hpp"
#include "core/domain/convex_polygon.hpp"
#include "core/domain/unit_square.hpp"
#include "core/eval/patch_evaluator.hpp"

namespace pl::bench {

namespace {

void print(const char* loop, std::size_t grain, const QuietBusy& t) {
  char name[64];
  std::snprintf(name, sizeof name, "grain_%s_%zu_ms", loop, grain);
  figure(name, t.quiet, "ms");
  std::snprintf(name, sizeof name, "grain_%s_%zu_ms_busy", loop, grain);
  figure(name, t.busy, "ms");
}

std::vector<std::size_t> grains(std::size_t n, std::initializer_list<std::size_t> list) {
  std::vector<std::size_t> g(list);
  g.push_back(n);
  return g;
}

}  // namespace

void bench_grains(const Options& o) {
  const int repeats = o.quick ? 2 : 30, rounds = o.quick ? 1 : 3;
  {
    UnitSquareDomain square;
    PatchEvaluator ev(random_bicubic(),
                      std::make_shared<const Tessellation>(square.tessellate(o.quick ? 30 : 315)));
    const std::size_t k = 5;
    Vec3 p = ev.patch().control_point(k);
    int step = 0;
    for (std::size_t g :
         grains(ev.sample_count(), {64, 128, 256, 512, 1024, 2048, 4096, 8192, 16384})) {
      PatchEvaluator::Grains gs = ev.grains();
      gs.update = g;
      ev.set_grains(gs);
      ev.prepare_influence(k);
      print("update", g, median_ms_quiet_busy(repeats, rounds, [&] {
              p.z += (++step % 2 ? 1e-3 : -1e-3);
              ev.move_control_point(k, p);
            }));
    }
  }
  const auto patch = cagd86();
  const auto tess = std::make_shared<const Tessellation>(
      ConvexPolygonDomain::regular(5).tessellate(o.quick ? 30 : 200));
  {
    PatchEvaluator ev(std::shared_ptr<Patch>(patch->clone()), tess);
    for (std::size_t g : grains(ev.sample_count(), {256, 512, 1024, 2048, 4096, 8192})) {
      PatchEvaluator::Grains gs = ev.grains();
      gs.evaluate = g;
      ev.set_grains(gs);
      print("evaluate", g,
            median_ms_quiet_busy(o.quick ? 2 : 10, rounds, [&] { ev.evaluate_all(); }));
    }
  }
  {
    PatchEvaluator ev(std::shared_ptr<Patch>(patch->clone()), tess);
    // More points than the evaluator keeps columns for, in turn: every call builds one.
    std::vector<std::size_t> ks;
    for (int j = 1; j <= 3; ++j)
      ks.push_back(patch->index(0, j, 1)), ks.push_back(patch->index(2, j, 1));
    ev.set_column_budget(0);
    std::size_t next = 0;
    for (std::size_t g : grains(ev.sample_count(), {1024, 2048, 4096, 8192, 16384})) {
      PatchEvaluator::Grains gs = ev.grains();
      gs.column = g;
      ev.set_grains(gs);
      print("column", g, median_ms_quiet_busy(o.quick ? 2 : 12, rounds, [&] {
              ev.prepare_influence(ks[next++ % ks.size()]);
            }));
    }
  }
}

}  // namespace pl::bench
