// The benchmark program: prints "figure NAME VALUE UNIT" lines. Run without arguments for real
// figures (Release build), with --quick for a seconds-long smoke run, with --grains for the sweep
// that chose the parallel grains, with --only NAME,... for some of the benchmarks (machine,
// bezier, gb, gb_face, interior, engine, catmull_clark, cad, cad_ngon, curve, curve_scale,
// schemes). The machine's floors (memory stream, scalar arithmetic) come first.
#include <oneapi/tbb/info.h>

#include <cstring>
#include <string>

#include "bench_common.hpp"

int main(int argc, char** argv) {
  pl::bench::Options options;
  std::string only;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--quick") == 0) {
      options.quick = true;
    } else if (std::strcmp(argv[i], "--grains") == 0) {
      options.grains = true;
    } else if (std::strcmp(argv[i], "--only") == 0 && i + 1 < argc) {
      only.append(",").append(argv[++i]).append(",");
    } else {
      std::fprintf(stderr,
                   "usage: patchlab_bench [--quick] [--grains] [--only "
                   "machine,bezier,gb,gb_face,interior,engine,"
                   "catmull_clark,cad,cad_ngon,curve,curve_scale,schemes]\n");
      return 2;
    }
  }
  std::printf("# patchlab_bench: %d threads (oneTBB)%s\n", oneapi::tbb::info::default_concurrency(),
              options.quick ? " (quick mode: figures are not meaningful)" : "");
  const auto run = [&](const char* name, void (*bench)(const pl::bench::Options&)) {
    if (only.empty() || only.find(std::string(",").append(name).append(",")) != std::string::npos)
      bench(options);
  };
  if (options.grains) {
    pl::bench::bench_grains(options);
    return 0;
  }
  run("machine", pl::bench::bench_machine);  // the floors first, beside every other figure
  run("bezier", pl::bench::bench_bezier);
  run("gb", pl::bench::bench_gb);
  run("gb_face", pl::bench::bench_gb_face);
  run("interior", pl::bench::bench_interior);
  run("engine", pl::bench::bench_engine);
  run("catmull_clark", pl::bench::bench_catmull_clark);
  run("cad", pl::bench::bench_cad);
  run("cad_ngon", pl::bench::bench_cad_ngon);
  run("curve", pl::bench::bench_curve);
  run("curve_scale", pl::bench::bench_curve_scale);
  run("schemes", pl::bench::bench_schemes);
  run("scene_commands", pl::bench::bench_scene_commands);
  return 0;
}
