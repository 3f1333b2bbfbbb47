// The classic sample scenes in assets/classic are oriented like every other surface: the normal
// Su x Sv points to the outside of closed shapes, so shaded views show their front faces there.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "classic_test_util.hpp"
#include "core/geometry/differential_geometry.hpp"
#include "core/io/scene_io.hpp"
#include "test_util.hpp"

namespace pl {
namespace {

std::filesystem::path asset(const char* name) {
  return std::filesystem::path(PATCHLAB_SOURCE_DIR) / "assets" / name;
}

// Sphere R = 1 about the origin: outward unit normal (p - c) / R, H = -1/R (the surface bends
// away from its normal), K = 1/R^2. Cylinder R = 0.5 about the axis x = 3, y = 0: outward normal,
// H = -1/(2R), K = 0.
TEST(ClassicAssets, NurbsSampleNormalsPointOutwards) {
  const Scene scene = read_scene(asset("classic/nurbs.json"));
  ASSERT_EQ(scene.patches.size(), 2u);
  const Patch& sphere = *scene.patches[0].patch;
  const Patch& cylinder = *scene.patches[1].patch;
  double sphere_n = 0, sphere_h = 0, sphere_k = 0, cyl_n = 0, cyl_h = 0, cyl_k = 0;
  // Away from the sphere's pole rows, where the normal is undefined.
  for (const Vec2& x : test::random_domain_points(400, 11, 0.01, 0.99)) {
    const SurfaceJet s = sphere.evaluate(x);
    const SurfaceGeometry g = differential_geometry(s);
    ASSERT_EQ(g.status, GeometryStatus::Regular);
    sphere_n = std::max(sphere_n, glm::length(g.normal - s.p));
    sphere_h = std::max(sphere_h, std::fabs(g.mean + 1.0));
    sphere_k = std::max(sphere_k, std::fabs(g.gaussian - 1.0));
    const SurfaceJet c = cylinder.evaluate(x);
    const SurfaceGeometry h = differential_geometry(c);
    ASSERT_EQ(h.status, GeometryStatus::Regular);
    const Vec3 radial = (c.p - Vec3(3, 0, c.p.z)) / 0.5;
    cyl_n = std::max(cyl_n, glm::length(h.normal - radial));
    cyl_h = std::max(cyl_h, std::fabs(h.mean + 1.0));
    cyl_k = std::max(cyl_k, std::fabs(h.gaussian));
  }
  std::printf(
      "nurbs sample: sphere |n - p| %.3g, |H + 1| %.3g, |K - 1| %.3g; cylinder "
      "|n - radial| %.3g, |H + 1| %.3g, |K| %.3g\n",
      sphere_n, sphere_h, sphere_k, cyl_n, cyl_h, cyl_k);
  // Exact quadrics: rounding only (the bound of the NurbsPatch::sphere test's figures).
  for (double worst : {sphere_n, sphere_h, sphere_k, cyl_n, cyl_h, cyl_k}) EXPECT_LT(worst, 1e-10);
}

}  // namespace
}  // namespace pl
