// The work bound (docs/limits.md) counts a curve's samples as a surface's: a scene over it is
// refused before any evaluation, and the density the message names is one that fits.
#include <gtest/gtest.h>

#include <regex>

#include "app/cli/work_limits.hpp"
#include "core/base/data_error.hpp"
#include "core/io/input_limits.hpp"

namespace pl {
namespace {

// A clamped uniform cubic B-spline with `points` control points (points - 3 spans).
SceneCurve long_bspline(std::size_t points) {
  SceneCurve c;
  c.type = CurveType::BSpline;
  c.degree = 3;
  c.points.resize(points);
  for (std::size_t i = 0; i < points; ++i) c.points[i] = Vec3(double(i), std::sin(0.1 * i), 0);
  const std::size_t spans = points - 3;
  c.knots.assign(4, 0.0);
  for (std::size_t k = 1; k < spans; ++k) c.knots.push_back(double(k) / double(spans));
  c.knots.insert(c.knots.end(), 4, 1.0);
  return c;
}

std::string refusal(const Scene& s, int density) {
  try {
    check_work_limits(s, density, "big.json");
  } catch (const DataError& e) {
    return e.what();
  }
  return "";
}

TEST(CurveWorkBound, TheNamedDensityFits) {
  Scene s;
  s.curves.push_back(long_bspline(200003));  // 200,000 spans: 6.6 million samples at density 32
  EXPECT_EQ(estimated_samples(s, 32), 200000u * 33);
  const std::string e = refusal(s, 32);
  std::smatch m;
  ASSERT_TRUE(std::regex_search(e, m, std::regex("use --density ([0-9]+) or less"))) << e;
  const int fits = std::stoi(m[1]);
  // Samples grow linearly with the density on a curve; the message assumed the square and
  // named 25, which is over the bound too.
  EXPECT_EQ(refusal(s, fits), "") << fits;
  EXPECT_NE(refusal(s, fits + 1), "") << fits;
  EXPECT_EQ(fits, int(kMaxSamples / 200000) - 1);
}

TEST(CurveWorkBound, ACurveTooLongForAnyDensityIsRefusedWithTheReason) {
  Scene s;
  s.curves.push_back(long_bspline(kMaxSamples / 2 + 10));
  const std::string e = refusal(s, 1);
  EXPECT_NE(e.find("big.json: at density 1 the scene takes about"), std::string::npos) << e;
  EXPECT_NE(e.find("too many surfaces or curve spans"), std::string::npos) << e;
  EXPECT_EQ(e.find("use --density"), std::string::npos) << e;
}

TEST(CurveWorkBound, ManyShortCurvesCountAsTheirSpans) {
  Scene s;
  SceneCurve c;
  c.type = CurveType::Bezier;
  c.points = {Vec3(0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)};
  s.curves.assign(40000, c);
  EXPECT_EQ(estimated_samples(s, 32), 40000u * 33);
  EXPECT_EQ(refusal(s, 32), "");
  EXPECT_NE(refusal(s, 105), "");  // 40,000 x 106 > 4,194,304
}

}  // namespace
}  // namespace pl
