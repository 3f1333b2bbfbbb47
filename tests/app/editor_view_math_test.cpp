// The editor's picking and camera-control maths against independent computations.
#include <gtest/gtest.h>

#include <cmath>

#include "app/editor/logic/camera_control.hpp"
#include "app/editor/logic/view_math.hpp"

namespace pl {
namespace {

Camera test_camera(bool ortho) {
  Box box;
  box.add(Vec3(-1, -1, -0.5));
  box.add(Vec3(1, 1, 0.5));
  Camera c = preset_camera(ViewPreset::Iso, box, 800.0 / 600.0, ortho);
  return c;
}

const ViewRect kRect{10, 20, 800, 600};

TEST(EditorViewMath, ProjectionAndWindowRayAgree) {
  for (bool ortho : {false, true}) {
    const Camera c = test_camera(ortho);
    const Vec3 p(0.3, -0.4, 0.2);
    const auto s = project_to_window(c, kRect, p);
    ASSERT_TRUE(s);
    const Ray ray = window_ray(c, kRect, *s);
    // The ray through p's pixel passes through p.
    const Vec3 w = p - ray.origin;
    const Vec3 off = w - glm::dot(w, ray.direction) * ray.direction;
    EXPECT_LT(glm::length(off), 1e-9) << "ortho " << ortho;
    // The target projects to the centre of the rectangle.
    const auto centre = project_to_window(c, kRect, c.target);
    EXPECT_NEAR(centre->x, kRect.x + kRect.width / 2, 1e-9);
    EXPECT_NEAR(centre->y, kRect.y + kRect.height / 2, 1e-9);
  }
}

TEST(EditorViewMath, PickPrefersNearestOnScreenThenNearestToEye) {
  const Camera c = test_camera(false);
  const Vec3 a(0, 0, 0);
  const Vec3 behind = a - 0.5 * c.forward();  // same pixel, nearer the eye
  const Vec3 far_off = a + 0.3 * c.right();   // elsewhere on screen
  const std::vector<Vec3> pts{a, behind, far_off};
  const Vec2 px = *project_to_window(c, kRect, a);
  EXPECT_EQ(pick_point(c, kRect, pts, {}, px, 8), 1);
  EXPECT_EQ(pick_point(c, kRect, pts, {true, false, true}, px, 8), 0);
  EXPECT_EQ(pick_point(c, kRect, pts, {}, px + Vec2(300, 0), 8), -1);
  const Vec2 pf = *project_to_window(c, kRect, far_off);
  EXPECT_EQ(pick_point(c, kRect, pts, {}, pf + Vec2(3, 0), 8), 2);
}

TEST(EditorViewMath, ViewPlaneDragFollowsTheCursorExactly) {
  const Camera c = test_camera(false);
  const Vec3 start(0.2, 0.1, 0.3);
  const Vec2 s0 = *project_to_window(c, kRect, start);
  const DragMotion m{start, s0};
  const Vec2 to = s0 + Vec2(37, -12);
  const Vec3 d = m.offset(c, kRect, to, std::nullopt);
  // The moved point projects under the cursor and stays at the same depth.
  const Vec2 s1 = *project_to_window(c, kRect, start + d);
  EXPECT_NEAR(s1.x, to.x, 1e-7);
  EXPECT_NEAR(s1.y, to.y, 1e-7);
  EXPECT_NEAR(glm::dot(d, c.forward()), 0, 1e-12);
  // And by the pixel scale the e2e test relies on.
  const double s = world_per_pixel(c, kRect, start);
  EXPECT_NEAR(glm::length(d - (37 * s * c.right() + 12 * s * c.up())), 0, 1e-12);
}

TEST(EditorViewMath, AxisDragMovesOnlyAlongTheAxis) {
  const Camera c = test_camera(false);
  const Vec3 start(0.2, 0.1, 0.3);
  const Vec2 s0 = *project_to_window(c, kRect, start);
  const DragMotion m{start, s0};
  const Vec3 d = m.offset(c, kRect, s0 + Vec2(40, 5), Vec3(1, 0, 0));
  EXPECT_GT(std::abs(d.x), 1e-3);
  EXPECT_EQ(d.y, 0);
  EXPECT_EQ(d.z, 0);
  // The moved point is where the cursor ray passes closest to the axis line.
  const Ray r = window_ray(c, kRect, s0 + Vec2(40, 5));
  const Vec3 q = start + d;
  const Vec3 w = q - r.origin;
  const Vec3 perp = w - glm::dot(w, r.direction) * r.direction;
  EXPECT_NEAR(glm::dot(perp, Vec3(1, 0, 0)), 0, 1e-9);
}

TEST(EditorCameraControl, OrbitKeepsThePivotOnScreen) {
  Camera c = test_camera(false);
  const Vec3 pivot(0.7, -0.2, 0.1);
  const Vec2 before = *project_to_window(c, kRect, pivot);
  orbit_about(c, pivot, 0.4, -0.2);
  const Vec2 after = *project_to_window(c, kRect, pivot);
  EXPECT_NEAR(before.x, after.x, 1e-7);
  EXPECT_NEAR(before.y, after.y, 1e-7);
}

TEST(EditorCameraControl, ZoomKeepsThePointUnderTheCursor) {
  for (bool ortho : {false, true}) {
    Camera c = test_camera(ortho);
    const Vec2 cursor(200, 150);
    const auto q = intersect_plane(window_ray(c, kRect, cursor), c.target, c.forward());
    ASSERT_TRUE(q);
    const double d0 = c.distance;
    zoom_at(c, kRect, cursor, 1.5);
    EXPECT_NEAR(c.distance, d0 / 1.5, 1e-12);
    const Vec2 s = *project_to_window(c, kRect, *q);
    EXPECT_NEAR(s.x, cursor.x, 1e-7);
    EXPECT_NEAR(s.y, cursor.y, 1e-7);
  }
}

TEST(EditorCameraControl, PanMovesTheSceneWithTheCursor) {
  Camera c = test_camera(false);
  const Vec2 before = *project_to_window(c, kRect, c.target);
  const Vec3 t = c.target;
  pan_pixels(c, kRect, 25, -10);
  const Vec2 after = *project_to_window(c, kRect, t);
  EXPECT_NEAR(after.x - before.x, 25, 1e-7);
  EXPECT_NEAR(after.y - before.y, -10, 1e-7);
}

}  // namespace
}  // namespace pl
