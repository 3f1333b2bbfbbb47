// The sample scenes of assets/curves show what their names say, checked numerically.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "core/analysis/curve_analysis.hpp"
#include "core/curve/curvature.hpp"
#include "core/io/scene_io.hpp"

namespace pl {
namespace {

Scene curve_asset(const char* name) {
  return read_scene(std::filesystem::path(PATCHLAB_SOURCE_DIR) / "assets" / "curves" / name);
}

TEST(CurveAssets, CircleAndConics) {
  const Scene s = curve_asset("nurbs-circle-and-conics.json");
  ASSERT_EQ(s.curves.size(), 4u);
  for (int i = 0; i <= 100; ++i)
    EXPECT_NEAR(curve_curvature(evaluate(s.curves[0], i / 100.0)), 1.0, 1e-12);
  EXPECT_NEAR(curve_length(s.curves[0]), 2 * M_PI, 1e-9 * 2 * M_PI);
  // The middle weight w of a conic arc: w < 1 ellipse, = 1 parabola, > 1 hyperbola.
  EXPECT_LT(s.curves[1].weights[1], 1.0);
  EXPECT_EQ(s.curves[2].weights[1], 1.0);
  EXPECT_GT(s.curves[3].weights[1], 1.0);
}

TEST(CurveAssets, KnotMultiplicityGivesC2C1C0) {
  const Scene s = curve_asset("bspline-knot-multiplicity.json");
  ASSERT_EQ(s.curves.size(), 3u);
  auto jumps = [&](const SceneCurve& c) {
    const SplineCurve f = spline_form(c);
    const CurvePoint l = evaluate(f, std::nextafter(0.5, 0.0)), r = evaluate(f, 0.5);
    return std::array<double, 3>{glm::length(l.p - r.p), glm::length(l.d1 - r.d1),
                                 glm::length(l.d2 - r.d2)};
  };
  const auto c2 = jumps(s.curves[0]), c1 = jumps(s.curves[1]), c0 = jumps(s.curves[2]);
  EXPECT_LT(c2[1], 1e-9);
  EXPECT_LT(c2[2], 1e-6);
  EXPECT_LT(c1[1], 1e-9);
  EXPECT_GT(c1[2], 1.0);  // the double knot: second derivative (and curvature) jumps
  EXPECT_LT(c0[0], 1e-12);
  EXPECT_GT(c0[1], 1.0);  // the triple knot: a kink
}

TEST(CurveAssets, OneCubicThreeWays) {
  const Scene s = curve_asset("interpolating-hermite-bezier.json");
  ASSERT_EQ(s.curves.size(), 3u);
  for (int i = 0; i <= 200; ++i) {
    const double t = i / 200.0;
    const Vec3 a = evaluate(s.curves[0], t).p;
    EXPECT_LT(glm::length(evaluate(s.curves[1], t).p - Vec3(4, 0, 0) - a), 1e-14 * 4) << t;
    EXPECT_LT(glm::length(evaluate(s.curves[2], t).p - Vec3(8, 0, 0) - a), 1e-14 * 4) << t;
  }
}

TEST(CurveAssets, JointsG0G1G2) {
  const Scene s = curve_asset("joints-g0-g1-g2.json");
  const auto joints = curve_joints(s.curves);
  ASSERT_EQ(joints.size(), 3u);
  EXPECT_GT(joints[0].tangent_angle_deg, 1.0);
  EXPECT_LT(joints[1].tangent_angle_deg, 1e-9);
  EXPECT_GT(joints[1].curvature_jump, 1e-3);
  EXPECT_LT(joints[2].tangent_angle_deg, 1e-9);
  EXPECT_LT(joints[2].curvature_jump, 1e-9);
}

}  // namespace
}  // namespace pl
