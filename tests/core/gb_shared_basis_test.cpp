// Convex GB faces of a network share their basis (core/patch/gb/shared_basis.hpp): evaluated
// through the shared blocks, every sample of every face equals the face's own evaluate() to
// rounding, and the blocks are shared, not one per face.
#include <gtest/gtest.h>

#include "core/domain/tessellation_cache.hpp"
#include "core/eval/scene_surfaces.hpp"
#include "core/network/sample_networks.hpp"
#include "core/patch/gb/shared_basis.hpp"

namespace pl {
namespace {

TEST(GBSharedBasis, FacesThroughTheSharedBasisEqualTheirOwnEvaluation) {
  Scene scene;
  scene.network = cube_sphere_network(3, FaceScheme::GB);  // 54 quads, all on the regular square
  TessellationCache cache;
  const SharedBasisUse before = shared_basis_use();
  const SceneSurfaces ss = evaluate_scene(scene, 24, std::nullopt, cache, "cube sphere");
  const SharedBasisUse after = shared_basis_use();
  // A handful of blocks for the one tessellation, not one per face.
  EXPECT_GT(after.blocks, before.blocks);
  EXPECT_LE(after.blocks - before.blocks, 8u);
  double worst_p = 0, worst_d1 = 0, worst_d2 = 0;
  for (const SceneSurface& s : ss.surfaces) {
    const PatchEvaluator& ev = *s.evaluator;
    EXPECT_EQ(ev.patch().type(), "gb-ribbons");
    const auto& xs = ev.tessellation().points;
    for (std::size_t i = 0; i < xs.size(); ++i) {
      const SurfaceJet a = ev.jets()[i], b = ev.patch().evaluate(xs[i]);
      const double d1 = glm::length(b.su) + glm::length(b.sv);
      const double d2 = 1 + glm::length(b.suu) + glm::length(b.suv) + glm::length(b.svv);
      worst_p = std::max(worst_p, glm::length(a.p - b.p));  // the sphere has radius 1
      worst_d1 = std::max(worst_d1, (glm::length(a.su - b.su) + glm::length(a.sv - b.sv)) / d1);
      worst_d2 = std::max(worst_d2, (glm::length(a.suu - b.suu) + glm::length(a.suv - b.suv) +
                                     glm::length(a.svv - b.svv)) /
                                        d2);
    }
  }
  std::printf("[ shared basis ] %zu faces: positions %.3g, first derivatives %.3g, second %.3g\n",
              ss.surfaces.size(), worst_p, worst_d1, worst_d2);
  EXPECT_LT(worst_p, 1e-14);
  EXPECT_LT(worst_d1, 1e-12);
  EXPECT_LT(worst_d2, 1e-10);
}

TEST(GBSharedBasis, ABypassEvaluatesFacesOnTheirOwn) {
  // Throughput figures compare a face evaluated on its own: under a bypass no block is kept or
  // used.
  Scene scene;
  scene.network = cube_sphere_network(2, FaceScheme::GB);
  TessellationCache cache;
  const SceneSurfaces shared = evaluate_scene(scene, 19, std::nullopt, cache, "s");
  const SharedBasisUse before = shared_basis_use();
  SharedBasisUse after;
  {
    const SharedBasisBypass alone;
    TessellationCache other;
    const SceneSurfaces own = evaluate_scene(scene, 19, std::nullopt, other, "s");
    after = shared_basis_use();
    // On its own a face runs its SIMD path: the shared sums' numbers to rounding.
    double worst = 0;
    for (std::size_t s = 0; s < own.surfaces.size(); ++s) {
      const PatchEvaluator& ev = *own.surfaces[s].evaluator;
      for (std::size_t i = 0; i < ev.sample_count(); ++i)
        worst = std::max(worst,
                         glm::length(ev.jets()[i].p - shared.surfaces[s].evaluator->jets()[i].p));
    }
    EXPECT_LT(worst, 1e-14);  // the sphere has radius 1
  }
  EXPECT_EQ(after.blocks, before.blocks);
}

}  // namespace
}  // namespace pl
