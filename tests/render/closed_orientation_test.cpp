// Which side of a closed network faces out: the sign of the volume its meshes enclose, and the
// DrawScene flag the renderer uses to draw only the outer side of a solid seen from outside.
#include <gtest/gtest.h>

#include "render/draw_scene_builder.hpp"
#include "core/domain/tessellation_cache.hpp"
#include "core/eval/scene_surfaces.hpp"
#include "core/network/sample_networks.hpp"
#include "render/draw_scene.hpp"

namespace pl {
namespace {

// The unit cube at `corner` as six two-triangle meshes, counter-clockwise seen from outside.
std::vector<SurfaceMesh> cube(const Vec3& corner) {
  const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  std::vector<SurfaceMesh> meshes;
  for (const auto& f : faces) {
    SurfaceMesh m;
    for (int k = 0; k < 4; ++k) {
      const int c = f[k];
      m.positions.push_back(corner + Vec3(c & 1, (c >> 1) & 1, (c >> 2) & 1));
    }
    m.triangles = {{0, 1, 2}, {0, 2, 3}};
    meshes.push_back(m);
  }
  return meshes;
}

TEST(ClosedOrientation, TheEnclosedVolumeSaysWhichWayTheNormalsFace) {
  // The origin inside, outside, or far away: the sign does not depend on it.
  for (const Vec3& corner : {Vec3(-0.5), Vec3(2, 3, -7), Vec3(1e3, -2e3, 5e2)}) {
    std::vector<SurfaceMesh> meshes = cube(corner);
    EXPECT_EQ(enclosed_volume_sign(meshes), 1);
    for (SurfaceMesh& m : meshes)
      for (auto& t : m.triangles) std::swap(t[1], t[2]);
    EXPECT_EQ(enclosed_volume_sign(meshes), -1);
  }
  // Flat through the origin: no volume, no side.
  std::vector<SurfaceMesh> flat = cube(Vec3(-0.5));
  for (SurfaceMesh& m : flat)
    for (Vec3& p : m.positions) p.z = 0;
  EXPECT_EQ(enclosed_volume_sign(flat), 0);
}

DrawScene draw_of(const Scene& scene) {
  TessellationCache cache;
  return build_draw_scene(scene, evaluate_scene(scene, 4, std::nullopt, cache, "cube sphere"));
}

TEST(ClosedOrientation, AClosedNetworkIsASolidWithItsFacesOutward) {
  Scene scene;
  scene.network = cube_sphere_network(2);
  // Face sides run counter-clockwise seen from the outward side (Su x Sv points out).
  EXPECT_EQ(draw_of(scene).closed_orientation, 1);
  // Without one face it bounds nothing: both sides are seen.
  scene.network->faces.pop_back();
  EXPECT_EQ(draw_of(scene).closed_orientation, 0);
}

}  // namespace
}  // namespace pl
