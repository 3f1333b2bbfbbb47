// The benchmark program: prints "figure NAME VALUE UNIT" lines. Run without arguments for real
// figures (Release build), with --quick for a seconds-long smoke run.
#include <omp.h>

#include <cstring>

#include "bench_common.hpp"

int main(int argc, char** argv) {
  pl::bench::Options options;
  const char* only = nullptr;  // --only NAME: that benchmark alone (e.g. --only curve)
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--quick") == 0) options.quick = true;
    if (std::strcmp(argv[i], "--only") == 0 && i + 1 < argc) only = argv[++i];
  }
  std::printf("# patchlab_bench: %d OpenMP threads%s\n", omp_get_max_threads(),
              options.quick ? " (quick mode: figures are not meaningful)" : "");
  if (!only || std::strcmp(only, "bezier") == 0) pl::bench::bench_bezier(options);
  if (!only || std::strcmp(only, "gb") == 0) pl::bench::bench_gb(options);
  if (!only || std::strcmp(only, "gb_face") == 0) pl::bench::bench_gb_face(options);
  if (!only || std::strcmp(only, "engine") == 0) pl::bench::bench_engine(options);
  if (!only || std::strcmp(only, "catmull_clark") == 0) pl::bench::bench_catmull_clark(options);
  if (!only || std::strcmp(only, "cad") == 0) pl::bench::bench_cad(options);
  if (!only || std::strcmp(only, "curve") == 0) pl::bench::bench_curve(options);
  return 0;
}
