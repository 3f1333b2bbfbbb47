// The cost of one n-sided network GB face at the default density, n = 8 .. 64 (faces of up to 64
// sides are allowed): filling it (tangent planes, Chiyokura–Kimura ribbons, the gb-ribbons patch),
// tessellating its domain and evaluating every sample with derivatives, normals and curvatures,
// as `patchlab analyze` does. Printed per face and per sample; the cost per sample may grow
// linearly in n (every sample blends all n ribbons), so it is also printed per sample and side,
// which should stay flat.
#include <cmath>

#include "bench_common.hpp"
#include "bench_scenes.hpp"
#include "core/eval/scene_surfaces.hpp"

namespace pl::bench {

void bench_gb_face(const Options& o) {
  constexpr int kDensity = 32;  // patchlab's default --density
  for (int n : {8, 16, 32, 64}) {
    Scene scene = wavy_ring_face(n, 0.1, 3, 0.05);
    scene.network->faces[0].scheme = FaceScheme::GB;
    std::size_t samples = 0;
    const double ms = median_ms(o.quick ? 1 : 5, [&] {
      TessellationCache cache;  // a fresh one: the tessellation is part of the cost
      const SceneSurfaces s =
          evaluate_scene(scene, o.quick ? 4 : kDensity, std::nullopt, cache, "bench");
      samples = s.surfaces.at(0).evaluator->sample_count();
    });
    const std::string tag = "_n" + std::to_string(n);
    figure(("gb_face_ms" + tag).c_str(), ms, "ms");
    figure(("gb_face_samples" + tag).c_str(), double(samples), "samples");
    figure(("gb_face_ns_per_sample" + tag).c_str(), ms * 1e6 / samples, "ns");
    figure(("gb_face_ns_per_sample_side" + tag).c_str(), ms * 1e6 / samples / n, "ns");
  }
}

}  // namespace pl::bench
