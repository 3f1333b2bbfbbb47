// The names of a scene's surfaces (core/scene/surface_names.hpp), as the outputs print them: a
// face's or patch's own name, else face<i> / patch<i>; pieces of a split patch get .<k>. The
// evaluation lists the same names in the same order (network faces, then patches).
#include "core/scene/surface_names.hpp"

#include <gtest/gtest.h>

#include "core/domain/tessellation_cache.hpp"
#include "core/eval/scene_surfaces.hpp"
#include "network_test_util.hpp"

namespace pl {
namespace {

TEST(SurfaceNames, OwnNameElseIndexedDefault) {
  const Network n = test::sphere_blob(true);
  EXPECT_EQ(face_surface_name(n, 0), "face0");
  EXPECT_EQ(face_surface_name(n, 9), "face9");
  EXPECT_EQ(face_surface_name(n, 10), "bottom-tri");
  EXPECT_EQ(piece_name("lid", 1, 0), "lid");
  EXPECT_EQ(piece_name("lid", 3, 2), "lid.2");
}

TEST(SurfaceNames, TheEvaluationListsFacesByThem) {
  Scene scene;
  scene.network = test::sphere_blob(true);
  TessellationCache cache;
  const SceneSurfaces ss = evaluate_scene(scene, 2, std::nullopt, cache, "blob");
  ASSERT_EQ(ss.surfaces.size(), scene.network->faces.size());
  for (std::size_t i = 0; i < ss.surfaces.size(); ++i)
    EXPECT_EQ(ss.surfaces[i].name,
              i < 10 ? "face" + std::to_string(i) : scene.network->faces[i].name);
}

}  // namespace
}  // namespace pl
