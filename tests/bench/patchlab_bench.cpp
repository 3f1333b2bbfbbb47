// The benchmark program: prints "figure NAME VALUE UNIT" lines. Run without arguments for real
// figures (Release build), with --quick for a seconds-long smoke run.
#include <omp.h>

#include <cstring>

#include "bench_common.hpp"

int main(int argc, char** argv) {
  pl::bench::Options options;
  for (int i = 1; i < argc; ++i)
    if (std::strcmp(argv[i], "--quick") == 0) options.quick = true;
  std::printf("# patchlab_bench: %d OpenMP threads%s\n", omp_get_max_threads(),
              options.quick ? " (quick mode: figures are not meaningful)" : "");
  pl::bench::bench_bezier(options);
  pl::bench::bench_gb(options);
  pl::bench::bench_gb_face(options);
  pl::bench::bench_engine(options);
  pl::bench::bench_catmull_clark(options);
  pl::bench::bench_cad(options);
  return 0;
}
