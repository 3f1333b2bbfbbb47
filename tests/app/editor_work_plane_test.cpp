// The work plane's ray-plane maths and grid against independent computations.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "app/editor/logic/work_plane.hpp"

namespace pl {
namespace {

const ViewRect kRect{0, 0, 800, 600};

Camera test_camera(bool ortho) {
  Box box;
  box.add(Vec3(-2, -1, -0.5));
  box.add(Vec3(2, 1, 1.5));
  return preset_camera(ViewPreset::Iso, box, kRect.aspect(), ortho);
}

TEST(EditorWorkPlane, FramesAreOrthonormalAndRightHanded) {
  const Camera c = test_camera(false);
  for (WorkPlaneKind k :
       {WorkPlaneKind::View, WorkPlaneKind::XY, WorkPlaneKind::XZ, WorkPlaneKind::YZ}) {
    WorkPlane w{k, Vec3(0.3, -0.2, 0.7)};
    const PlaneFrame f = w.frame(c);
    EXPECT_EQ(f.origin, w.origin);
    EXPECT_NEAR(glm::length(f.u), 1, 1e-15);
    EXPECT_NEAR(glm::length(f.v), 1, 1e-15);
    EXPECT_NEAR(glm::dot(f.u, f.v), 0, 1e-15);
    EXPECT_LT(glm::length(glm::cross(f.u, f.v) - f.normal), 1e-15) << work_plane_name(k);
  }
  EXPECT_EQ(WorkPlane{WorkPlaneKind::XY}.frame(c).normal, Vec3(0, 0, 1));
  EXPECT_EQ(WorkPlane{WorkPlaneKind::XZ}.frame(c).normal, Vec3(0, -1, 0));
  EXPECT_EQ(WorkPlane{WorkPlaneKind::YZ}.frame(c).normal, Vec3(1, 0, 0));
  // The view plane faces the eye.
  const PlaneFrame v = WorkPlane{WorkPlaneKind::View}.frame(c);
  EXPECT_LT(glm::length(v.normal + c.forward()), 1e-15);
}

TEST(EditorWorkPlane, ClickLandsOnThePlaneUnderTheCursor) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> px(0, kRect.width), py(0, kRect.height);
  for (bool ortho : {false, true}) {
    const Camera c = test_camera(ortho);
    for (WorkPlaneKind k :
         {WorkPlaneKind::View, WorkPlaneKind::XY, WorkPlaneKind::XZ, WorkPlaneKind::YZ}) {
      const WorkPlane w{k, Vec3(0.25, 0.5, -0.125)};
      const PlaneFrame f = w.frame(c);
      int hits = 0;
      for (int i = 0; i < 50; ++i) {
        const Vec2 pixel(px(rng), py(rng));
        const Ray ray = window_ray(c, kRect, pixel);
        const auto p = w.hit(c, ray);
        if (!p) {
          // Only when the plane is behind the eye along this ray (or parallel to it).
          const double denom = glm::dot(ray.direction, f.normal);
          EXPECT_TRUE(std::abs(denom) < 1e-12 ||
                      glm::dot(f.origin - ray.origin, f.normal) / denom <= 0);
          continue;
        }
        ++hits;
        // On the plane, and under the cursor: it projects back to the pixel.
        EXPECT_NEAR(glm::dot(*p - f.origin, f.normal), 0, 1e-12);
        const auto back = project_to_window(c, kRect, *p);
        ASSERT_TRUE(back);
        EXPECT_LT(glm::length(*back - pixel), 1e-7) << work_plane_name(k) << " ortho " << ortho;
      }
      EXPECT_GT(hits, 10) << work_plane_name(k);
    }
  }
}

TEST(EditorWorkPlane, ParallelAndBehindRaysMiss) {
  const PlaneFrame xy;                                              // z = 0
  EXPECT_FALSE(intersect_plane_ahead({{0, 0, 1}, {1, 0, 0}}, xy));  // parallel
  EXPECT_FALSE(intersect_plane_ahead({{0, 0, 1}, {0, 0, 1}}, xy));  // behind
  const auto p = intersect_plane_ahead({{1, 2, 3}, {0, 0, -1}}, xy);
  ASSERT_TRUE(p);
  EXPECT_EQ(*p, Vec3(1, 2, 0));
}

TEST(EditorWorkPlane, GridStepsAreNiceAndLinesLieOnThePlane) {
  EXPECT_DOUBLE_EQ(grid_step(10, 10), 1);
  EXPECT_DOUBLE_EQ(grid_step(11, 10), 2);
  EXPECT_DOUBLE_EQ(grid_step(0.03, 10), 0.005);
  EXPECT_DOUBLE_EQ(grid_step(400, 10), 50);
  EXPECT_DOUBLE_EQ(grid_step(0, 10), 1);  // degenerate: a sane default
  const Camera c = test_camera(false);
  const WorkPlane w{WorkPlaneKind::XZ, Vec3(0.1, 0.4, 0.2)};
  const PlaneFrame f = w.frame(c);
  const double step = 0.25;
  const auto segs = grid_segments(f, Vec3(1.13, 7, -0.4), step, 4);
  ASSERT_EQ(segs.size(), 2u * 2 * 9 * 8);  // 9 lines each way, 8 cells long, 2 ends a segment
  for (const Vec3& p : segs) {
    EXPECT_NEAR(glm::dot(p - f.origin, f.normal), 0, 1e-15);
    // On multiples of the step from the origin, in both plane coordinates.
    const Vec2 uv = plane_coordinates(f, p);
    EXPECT_NEAR(uv.x / step, std::round(uv.x / step), 1e-9);
    EXPECT_NEAR(uv.y / step, std::round(uv.y / step), 1e-9);
  }
  // Centred on the grid point nearest the projected centre: u = 1.13 - 0.1 -> 1.0, v = -0.6 ->
  // -0.5.
  const Vec2 a = plane_coordinates(f, segs[0]), b = plane_coordinates(f, segs.back());
  EXPECT_NEAR(0.5 * (a.x + b.x), 1.0, 1e-12);
  EXPECT_NEAR(0.5 * (a.y + b.y), -0.5, 1e-12);
}

}  // namespace
}  // namespace pl
