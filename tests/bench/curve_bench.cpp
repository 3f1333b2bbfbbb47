// Dragging one point of a 1,000-point cubic B-spline against evaluating all its samples, in the
// same run.
#include <random>

#include "bench_common.hpp"
#include "core/eval/curve_samples.hpp"

namespace pl::bench {

void bench_curve(const Options& options) {
  const int n = options.quick ? 40 : 1000, p = 3, per_span = 16;
  SceneCurve c;
  c.type = CurveType::BSpline;
  c.degree = p;
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < n; ++i) c.points.push_back({i * 0.01, u(rng), u(rng)});
  c.knots.assign(p + 1, 0.0);
  for (int i = 1; i < n - p; ++i) c.knots.push_back(double(i) / (n - p));
  c.knots.insert(c.knots.end(), p + 1, 1.0);
  CurveSamples samples(c, per_span);
  const int repeats = options.quick ? 3 : 201;
  int step = 0;
  const double drag_ms = median_ms(repeats, [&] {
    const std::size_t i = n / 2;
    samples.move_point(i, c.points[i] + Vec3(0, 1e-3 * (++step % 7), 0));
  });
  const double full_ms = median_ms(options.quick ? 3 : 21, [&] { samples.evaluate_all(); });
  figure(n == 1000 ? "curve_drag_us_1000" : "curve_drag_us_quick", drag_ms * 1e3, "us");
  figure(n == 1000 ? "curve_full_eval_us_1000" : "curve_full_eval_us_quick", full_ms * 1e3, "us");
  figure("curve_drag_speedup", full_ms / drag_ms, "x");
}

}  // namespace pl::bench
