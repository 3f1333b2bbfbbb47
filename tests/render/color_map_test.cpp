// The colour map and its range: zero is neutral, the ends are the range, percentile clipping.
#include "render/color_map.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "render/display_settings.hpp"
#include "render/legend.hpp"

namespace pl {
namespace {

TEST(ColorRange, ZeroIsTheCentreAndTheEndsAreTheRange) {
  const ColorRange r{-2, 8};
  EXPECT_DOUBLE_EQ(r.normalized(0), 0.5);
  EXPECT_DOUBLE_EQ(r.normalized(-2), 0);
  EXPECT_DOUBLE_EQ(r.normalized(8), 1);
  EXPECT_DOUBLE_EQ(r.normalized(4), 0.75);
  EXPECT_DOUBLE_EQ(r.normalized(-1), 0.25);
  EXPECT_DOUBLE_EQ(r.normalized(100), 1);  // clamped
  EXPECT_DOUBLE_EQ(r.normalized(std::nan("")), 0.5);
}

TEST(ColorMap, DivergesFromANeutralCentre) {
  const Rgb lo = color_map(0), mid = color_map(0.5), hi = color_map(1);
  EXPECT_GT(lo[2], lo[0]);            // blue end
  EXPECT_GT(hi[0], hi[2]);            // red end
  EXPECT_NEAR(mid[0], mid[2], 0.03);  // neutral: no hue bias at zero
  EXPECT_GT(mid[1], 0.9);
  EXPECT_EQ(color_map(-3), lo);
  EXPECT_EQ(color_map(7), hi);
}

TEST(ColorRange, AutomaticIsSymmetricAndClipsOutliers) {
  SurfaceMesh a, b;
  for (int i = 0; i < 99; ++i) a.mean.push_back(i % 2 ? 0.01 * i : -0.01 * i);
  b.mean = {1000.0, std::nan(""), std::numeric_limits<double>::infinity()};  // outlier, junk
  const SurfaceMesh* meshes[] = {&a, &b};
  const ColorRange r = automatic_range(meshes, CurvatureKind::Mean, 98.0);
  EXPECT_DOUBLE_EQ(r.lo, -r.hi);
  // 100 finite magnitudes 0.00 .. 0.98 and 1000: the 98th percentile is 0.97 (index 97).
  EXPECT_NEAR(r.hi, 0.97, 1e-12);
  const ColorRange all = automatic_range(meshes, CurvatureKind::Mean, 100.0);
  EXPECT_DOUBLE_EQ(all.hi, 1000.0);
}

TEST(ColorRange, FlatSurfaceGetsAUsableRange) {
  SurfaceMesh flat;
  flat.gaussian.assign(10, 0.0);
  const SurfaceMesh* meshes[] = {&flat};
  const ColorRange r = automatic_range(meshes, CurvatureKind::Gaussian);
  EXPECT_LT(r.lo, 0);
  EXPECT_GT(r.hi, 0);
}

TEST(Legend, TickLabels) {
  EXPECT_EQ(format_tick(0), "0");
  EXPECT_EQ(format_tick(-0.353125), "-0.353");
  EXPECT_EQ(format_tick(1250), "1.25e+03");
  EXPECT_EQ(format_tick(3.2e-5), "3.2e-05");
}

TEST(DisplayMode, ParsesCombinations) {
  const DisplaySettings a = parse_display_mode("mean+isophotes+control-net");
  EXPECT_EQ(a.base, BaseMode::Curvature);
  EXPECT_EQ(a.curvature, CurvatureKind::Mean);
  EXPECT_TRUE(a.isophote_lines);
  EXPECT_TRUE(a.control_net);
  const DisplaySettings b = parse_display_mode("isophotes");
  EXPECT_EQ(b.base, BaseMode::Isophotes);
  EXPECT_FALSE(b.isophote_lines);
  const DisplaySettings c = parse_display_mode("control-net");
  EXPECT_EQ(c.base, BaseMode::Shaded);
  EXPECT_EQ(parse_display_mode("kmin").curvature, CurvatureKind::Kmin);
  EXPECT_EQ(parse_display_mode("zebra+borders+network").base, BaseMode::Zebra);
}

TEST(DisplayMode, RejectsUnknownAndConflictingTokens) {
  EXPECT_THROW(parse_display_mode("mean+gaussian"), std::invalid_argument);
  EXPECT_THROW(parse_display_mode("shaded+zebra"), std::invalid_argument);
  EXPECT_THROW(parse_display_mode("wireframe"), std::invalid_argument);
  EXPECT_THROW(parse_display_mode(""), std::invalid_argument);
  EXPECT_THROW(parse_display_mode("mean+"), std::invalid_argument);
}

}  // namespace
}  // namespace pl
