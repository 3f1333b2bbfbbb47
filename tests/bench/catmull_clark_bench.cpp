// Figures of the Catmull-Clark n-gon cost: a single n-sided face (n ptex faces) evaluated at the
// CLI's default density 32, as `patchlab export` does it: the limit's construction (refinement,
// patch table, stencils) and every piece's samples with normals and curvatures. Per-sample cost
// should be flat in n; the construction grows with n^2 (every patch point near the centre holds
// the whole ring).
#include <cmath>

#include "bench_common.hpp"
#include "core/domain/tessellation_cache.hpp"
#include "core/eval/patch_evaluator.hpp"
#include "core/patch/catmull_clark_patch.hpp"

namespace pl::bench {

void bench_catmull_clark(const Options& options) {
  const int density = options.quick ? 4 : 32;
  const std::vector<int> sizes =
      options.quick ? std::vector<int>{8, 16} : std::vector<int>{32, 128, 256};
  for (const int n : sizes) {
    std::vector<Vec3> v;
    std::vector<int> loop;
    for (int i = 0; i < n; ++i) {
      const double a = 2 * M_PI * i / n;
      v.push_back({std::cos(a), std::sin(a), 0.1 * std::sin(3 * a)});
      loop.push_back(i);
    }
    std::size_t samples = 0;
    std::shared_ptr<CatmullClarkPatch> cc;
    const double setup = median_ms(options.quick ? 1 : 3, [&] {
      cc = std::make_shared<CatmullClarkPatch>(v, std::vector<std::vector<int>>{loop});
    });
    TessellationCache cache;
    const auto pieces = cc->surface_pieces();
    const double eval = median_ms(options.quick ? 1 : 3, [&] {
      samples = 0;
      for (const auto& piece : pieces) {
        PatchEvaluator ev(piece, cache.get(piece->domain(), density));
        samples += ev.sample_count();
      }
    });
    const std::string s = std::to_string(n);
    figure(("cc_ngon_ms_n" + s).c_str(), setup + eval, "ms");
    figure(("cc_ngon_setup_ms_n" + s).c_str(), setup, "ms");
    figure(("cc_ngon_eval_us_per_sample_n" + s).c_str(), 1e3 * eval / double(samples), "us");
    figure(("cc_ngon_samples_n" + s).c_str(), double(samples), "samples");
  }
}

}  // namespace pl::bench
