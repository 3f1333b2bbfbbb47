// Checks of a live SceneEvaluation against a from-scratch evaluation of the same scene.
#pragma once

#include <gtest/gtest.h>

#include "core/eval/scene_evaluation.hpp"

namespace pl::test {

// Every sample of a equals b's to 1e-12 relative to the largest value of that derivative order.
inline void expect_same_samples(const PatchEvaluator& a, const PatchEvaluator& b,
                                const std::string& what = "") {
  ASSERT_EQ(a.sample_count(), b.sample_count()) << what;
  EXPECT_EQ(a.patch().control_points(), b.patch().control_points()) << what;
  if (a.jets().empty() || b.jets().empty()) {  // compact storage: positions and normals
    double scale = 0, err = 0, normal = 0;
    for (std::size_t i = 0; i < a.sample_count(); ++i) {
      scale = std::max(scale, glm::length(b.position(i)));
      err = std::max(err, glm::length(a.position(i) - b.position(i)));
      normal = std::max(normal, glm::length(a.geometry()[i].normal - b.geometry()[i].normal));
    }
    EXPECT_LE(err, 1e-12 * scale) << what;
    EXPECT_LE(normal, 1e-12) << what;
    return;
  }
  double scale[3] = {0, 0, 0}, err[3] = {0, 0, 0};
  for (std::size_t i = 0; i < a.sample_count(); ++i) {
    const SurfaceJet &ja = a.jets()[i], &jb = b.jets()[i];
    const Vec3 da[6] = {ja.p, ja.su, ja.sv, ja.suu, ja.suv, ja.svv};
    const Vec3 db[6] = {jb.p, jb.su, jb.sv, jb.suu, jb.suv, jb.svv};
    for (int c = 0; c < 6; ++c) {
      const int order = c == 0 ? 0 : c < 3 ? 1 : 2;
      scale[order] = std::max(scale[order], glm::length(db[c]));
      err[order] = std::max(err[order], glm::length(da[c] - db[c]));
    }
  }
  for (int o = 0; o < 3; ++o) EXPECT_LE(err[o], 1e-12 * scale[o]) << what << " order " << o;
}

// The live evaluation has the surfaces, names, shared edges, projected vertices and samples of a
// fresh evaluation of `scene` at `density`.
inline void expect_equals_fresh_evaluation(const SceneEvaluation& live, const Scene& scene,
                                           int density) {
  TessellationCache cache;
  const SceneSurfaces fresh = evaluate_scene(scene, density, live.scheme(), cache, "fresh");
  const SceneSurfaces& ss = live.surfaces();
  ASSERT_EQ(ss.surfaces.size(), fresh.surfaces.size());
  for (std::size_t i = 0; i < ss.surfaces.size(); ++i) {
    const SceneSurface &a = ss.surfaces[i], &b = fresh.surfaces[i];
    const std::string what = "surface " + std::to_string(i);
    EXPECT_EQ(a.name, b.name) << what;
    EXPECT_EQ(a.face, b.face) << what;
    EXPECT_EQ(a.patch, b.patch) << what;
    EXPECT_EQ(a.patch_side, b.patch_side) << what;
    EXPECT_EQ(a.evaluator->patch().type(), b.evaluator->patch().type()) << what;
    expect_same_samples(*a.evaluator, *b.evaluator, what);
  }
  ASSERT_EQ(ss.shared_edges.size(), fresh.shared_edges.size());
  for (std::size_t i = 0; i < ss.shared_edges.size(); ++i) {
    const SharedEdge &a = ss.shared_edges[i], &b = fresh.shared_edges[i];
    EXPECT_EQ(a.edge, b.edge);
    for (int k = 0; k < 2; ++k) {
      EXPECT_EQ(a.surface[k], b.surface[k]);
      EXPECT_EQ(a.side[k], b.side[k]);
    }
  }
  ASSERT_EQ(ss.projected_vertices.size(), fresh.projected_vertices.size());
  for (std::size_t i = 0; i < ss.projected_vertices.size(); ++i) {
    EXPECT_EQ(ss.projected_vertices[i].vertex, fresh.projected_vertices[i].vertex);
    EXPECT_NEAR(ss.projected_vertices[i].max_angle_deg, fresh.projected_vertices[i].max_angle_deg,
                1e-9);
  }
}

}  // namespace pl::test
