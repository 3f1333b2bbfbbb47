// The machine's own floors, printed before the other figures so that runs on different machines
// compare as ratios: a memory stream (bytes per second moved by one thread, and by all) and a
// scalar arithmetic rate (double multiply-adds per second on one thread, not vectorised).
//   machine_memory_stream_gb_per_s, machine_memory_stream_gb_per_s_all_threads: the triad
//     a[i] = b[i] + s * c[i] over arrays of 32 MB each (well past the caches), 24 bytes a step;
//   machine_scalar_gflops: eight independent chains x = x * m + k, 2 flops a step each.
#include <oneapi/tbb/parallel_for.h>

#include <cstddef>
#include <vector>

#include "bench_common.hpp"

namespace pl::bench {

namespace {

// Milliseconds per triad sweep over the arrays, the median of `repeats`.
double triad_ms(std::vector<double>& a, const std::vector<double>& b, const std::vector<double>& c,
                int repeats, bool all_threads) {
  const double s = 1.0000001;
  return median_ms(repeats, [&] {
    const auto sweep = [&](std::size_t lo, std::size_t hi) {
      for (std::size_t i = lo; i < hi; ++i) a[i] = b[i] + s * c[i];
    };
    if (all_threads)
      oneapi::tbb::parallel_for(oneapi::tbb::blocked_range<std::size_t>(0, a.size(), 1 << 16),
                                [&](const auto& r) { sweep(r.begin(), r.end()); });
    else
      sweep(0, a.size());
  });
}

// Keeps a value alive past the optimiser.
void keep(double x) {
  asm volatile("" : : "x"(x));
}

}  // namespace

void bench_machine(const Options& options) {
  const std::size_t n = options.quick ? (1 << 16) : (4 << 20);  // 32 MB of doubles
  std::vector<double> a(n, 0.0), b(n, 1.0), c(n, 2.0);
  const int repeats = options.quick ? 3 : 15;
  const double bytes = 3.0 * sizeof(double) * double(n);
  figure("machine_memory_stream_gb_per_s", bytes / (triad_ms(a, b, c, repeats, false) * 1e6),
         "GB/s");
  figure("machine_memory_stream_gb_per_s_all_threads",
         bytes / (triad_ms(a, b, c, repeats, true) * 1e6), "GB/s");
  keep(a[n / 2]);

  // Eight chains hide the multiply-add latency. Each value passes through an empty asm in its own
  // register every step, so the compiler cannot pack the chains into vector lanes (the figure is
  // a scalar rate) nor fold the steps.
  const long steps = options.quick ? 100000 : 20000000;
  const double ms = median_ms(options.quick ? 1 : 5, [&] {
    double x0 = 1, x1 = 2, x2 = 3, x3 = 4, x4 = 5, x5 = 6, x6 = 7, x7 = 8;
    const double m = 0.9999999, k = 1e-7;
    for (long i = 0; i < steps; ++i) {
      x0 = x0 * m + k, x1 = x1 * m + k, x2 = x2 * m + k, x3 = x3 * m + k;
      x4 = x4 * m + k, x5 = x5 * m + k, x6 = x6 * m + k, x7 = x7 * m + k;
      asm volatile(""
                   : "+x"(x0), "+x"(x1), "+x"(x2), "+x"(x3), "+x"(x4), "+x"(x5), "+x"(x6),
                     "+x"(x7));
    }
    keep(x0 + x1 + x2 + x3 + x4 + x5 + x6 + x7);
  });
  figure("machine_scalar_gflops", 2.0 * 8 * double(steps) / (ms * 1e6), "GFLOP/s");
}

}  // namespace pl::bench
