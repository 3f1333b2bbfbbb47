// Camera maths: presets look from where they say, the frame is orthonormal (also at the poles),
// framing keeps every box corner inside the view, and interaction behaves.
#include "render/camera.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace pl {
namespace {

constexpr double kTol = 1e-12;

Box unit_box() {
  Box b;
  b.add(Vec3(-1, -2, -0.5));
  b.add(Vec3(3, 1, 0.5));
  return b;
}

void expect_near(const Vec3& a, const Vec3& b, double tol = kTol) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(a.z, b.z, tol);
}

TEST(Camera, PresetsLookFromTheirSide) {
  const Box b = unit_box();
  const struct {
    ViewPreset preset;
    Vec3 from;  // unit direction from the target to the eye
  } cases[] = {{ViewPreset::Front, {0, -1, 0}},
               {ViewPreset::Back, {0, 1, 0}},
               {ViewPreset::Left, {-1, 0, 0}},
               {ViewPreset::Right, {1, 0, 0}},
               {ViewPreset::Top, {0, 0, 1}},
               {ViewPreset::Bottom, {0, 0, -1}},
               {ViewPreset::Iso, glm::normalize(Vec3(1, -1, 1))}};
  for (const auto& c : cases) {
    const Camera cam = preset_camera(c.preset, b, 4.0 / 3.0);
    expect_near(glm::normalize(cam.eye() - cam.target), c.from);
    expect_near(cam.target, b.centre());
  }
}

TEST(Camera, FrameIsOrthonormalEverywhereIncludingThePoles) {
  Camera c;
  for (double pitch : {-1.5707963267948966, -1.0, 0.0, 0.3, 1.5707963267948966})
    for (double yaw : {-3.0, -1.0, 0.0, 2.0}) {
      c.yaw = yaw;
      c.pitch = pitch;
      EXPECT_NEAR(glm::length(c.forward()), 1, kTol);
      EXPECT_NEAR(glm::length(c.up()), 1, kTol);
      EXPECT_NEAR(glm::length(c.right()), 1, kTol);
      EXPECT_NEAR(glm::dot(c.forward(), c.up()), 0, kTol);
      EXPECT_NEAR(glm::dot(c.forward(), c.right()), 0, kTol);
    }
}

TEST(Camera, TopViewHasXRightAndYUp) {
  const Camera c = preset_camera(ViewPreset::Top, unit_box(), 1.0);
  expect_near(c.right(), Vec3(1, 0, 0));
  expect_near(c.up(), Vec3(0, 1, 0));
}

TEST(Camera, ViewMatrixPutsTheTargetOnTheAxisAtItsDistance) {
  const Camera c = preset_camera(ViewPreset::Iso, unit_box(), 1.5);
  const glm::dvec4 t = c.view() * glm::dvec4(c.target, 1.0);
  EXPECT_NEAR(t.x, 0, 1e-12);
  EXPECT_NEAR(t.y, 0, 1e-12);
  EXPECT_NEAR(-t.z, c.distance, 1e-12);
}

// Every box corner projects inside NDC, and the view is not needlessly loose: some corner
// touches the border within the margin.
void expect_framed(const Camera& c, const Box& b, double aspect, double margin) {
  const glm::dmat4 m = c.projection(aspect) * c.view();
  double extent = 0;
  for (int i = 0; i < 8; ++i) {
    const Vec3 p((i & 1) ? b.hi.x : b.lo.x, (i & 2) ? b.hi.y : b.lo.y, (i & 4) ? b.hi.z : b.lo.z);
    const glm::dvec4 q = m * glm::dvec4(p, 1.0);
    ASSERT_GT(q.w, 0);
    const double x = q.x / q.w, y = q.y / q.w, z = q.z / q.w;
    EXPECT_LE(std::abs(x), 1 + 1e-9);
    EXPECT_LE(std::abs(y), 1 + 1e-9);
    EXPECT_LE(std::abs(z), 1 + 1e-9);  // inside the clipping planes too
    extent = std::max({extent, std::abs(x), std::abs(y)});
  }
  EXPECT_GT(extent, 1 / margin - 0.15);
}

TEST(Camera, FramingKeepsEveryCornerInViewBothProjections) {
  const Box b = unit_box();
  for (double aspect : {0.5, 1.0, 16.0 / 9.0})
    for (bool ortho : {false, true})
      for (ViewPreset p : {ViewPreset::Iso, ViewPreset::Front, ViewPreset::Top, ViewPreset::Left}) {
        const Camera c = preset_camera(p, b, aspect, ortho);
        expect_framed(c, b, aspect, 1.08);
      }
}

// Points of a thin wavy strip running diagonally (so its box is mostly empty): frame_points fits
// the points themselves, so they fill more of the view than the box's corners allow, and every
// point is inside it.
TEST(Camera, FramingPointsIsTightAndKeepsEveryPointInView) {
  std::vector<Vec3> strip;
  for (int i = 0; i <= 20; ++i)
    for (int j = 0; j <= 2; ++j) {
      const double a = -2 + 0.2 * i, b = 0.1 * j;  // along and across the strip
      strip.emplace_back(0.8 * a - 0.6 * b, 0.6 * a + 0.8 * b, 0.3 * std::sin(0.5 * i));
    }
  Box box;
  for (const Vec3& p : strip) box.add(p);
  for (bool ortho : {false, true})
    for (double aspect : {0.75, 4.0 / 3.0}) {
      Camera tight = preset_camera(ViewPreset::Iso, box, aspect, ortho);
      const Camera loose = tight;
      tight.frame_points(strip, aspect);
      const glm::dmat4 m = tight.projection(aspect) * tight.view();
      double extent = 0;
      for (const Vec3& p : strip) {
        const glm::dvec4 q = m * glm::dvec4(p, 1.0);
        ASSERT_GT(q.w, 0);
        EXPECT_LE(std::abs(q.x / q.w), 1 + 1e-9);
        EXPECT_LE(std::abs(q.y / q.w), 1 + 1e-9);
        EXPECT_LE(std::abs(q.z / q.w), 1 + 1e-9);
        extent = std::max({extent, std::abs(q.x / q.w), std::abs(q.y / q.w)});
      }
      EXPECT_GT(extent, 1 / 1.08 - 0.05);  // touches the margin
      if (ortho) {
        EXPECT_LT(tight.half_height(), loose.half_height());
      } else {
        EXPECT_LT(tight.distance, loose.distance);
      }
    }
  // Everything at one place: that place in the middle of a unit box's view, not a zero distance.
  Camera one;
  const std::vector<Vec3> same(4, Vec3(1, 2, 3));
  one.frame_points(same, 1.0);
  expect_near(one.target, Vec3(1, 2, 3));
  EXPECT_GT(one.distance, 1.0);
}

TEST(Camera, OrbitPanZoom) {
  Camera c = preset_camera(ViewPreset::Front, unit_box(), 1.0);
  const double d = c.distance;
  const Vec3 target = c.target;
  c.orbit(1.5707963267948966, 0);  // a quarter turn: front -> right
  expect_near(glm::normalize(c.eye() - c.target), Vec3(1, 0, 0));
  EXPECT_NEAR(c.distance, d, kTol);
  c.orbit(0, 10);  // pitch clamps at the pole instead of flipping over
  EXPECT_NEAR(c.pitch, 1.5707963267948966, kTol);
  c.pan(0.5, -0.25);
  expect_near(c.target, target + 0.5 * c.right() - 0.25 * c.up());
  c.zoom(2);
  EXPECT_NEAR(c.distance, d / 2, kTol);
  c.zoom(0);  // ignored, not a division by zero
  EXPECT_NEAR(c.distance, d / 2, kTol);
}

TEST(Camera, ParsesPresetNamesOnly) {
  EXPECT_EQ(parse_view_preset("iso"), ViewPreset::Iso);
  EXPECT_EQ(parse_view_preset("bottom"), ViewPreset::Bottom);
  EXPECT_FALSE(parse_view_preset("Iso"));
  EXPECT_FALSE(parse_view_preset("camera.json"));
}

TEST(Camera, EmptyBoxLeavesTheCameraValid) {
  Camera c;
  const Camera before = c;
  c.frame(Box(), 1.0);
  EXPECT_EQ(c.distance, before.distance);
  EXPECT_TRUE(std::isfinite(c.projection(1.0)[0][0]));
}

}  // namespace
}  // namespace pl
