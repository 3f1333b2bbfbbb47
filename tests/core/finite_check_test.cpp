// check_finite of an evaluator checks its samples in parallel but names the first bad one in
// sample order, as a loop over them would: here a B-spline patch with one NaN point, which spoils
// only the samples of that point's support, in many of the check's tasks.
#include "core/mesh/finite_check.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/base/data_error.hpp"
#include "core/domain/unit_square.hpp"
#include "core/patch/bspline_patch.hpp"
#include "test_util.hpp"

namespace pl {
namespace {

TEST(FiniteCheck, NamesTheFirstBadSampleInOrder) {
  const std::vector<double> knots = {0, 0, 0, 0, 0.25, 0.5, 0.75, 1, 1, 1, 1};
  auto spline =
      std::make_shared<BSplinePatch>(3, 3, knots, knots, 7, 7, test::random_points(49, 12));
  auto tess = std::make_shared<const Tessellation>(UnitSquareDomain().tessellate(400));
  PatchEvaluator ev(spline, tess);
  EXPECT_NO_THROW(check_finite(ev, "s", "scene.json"));
  for (const std::size_t k :
       {std::size_t(48), std::size_t(8), std::size_t(0)}) {  // P_66, P_11, P_00
    auto broken = std::shared_ptr<Patch>(spline->clone());
    broken->set_control_point(k, Vec3(0, NAN, 0));
    const PatchEvaluator bad(broken, tess);
    // The first sample in order that is not finite: in the point's support (not every sample).
    std::size_t first = 0, count = 0;
    for (std::size_t i = bad.sample_count(); i-- > 0;)
      if (!bad.finite(i)) first = i, ++count;
    ASSERT_GT(count, 0u);
    ASSERT_LT(count, bad.sample_count() / 2);
    char where[96];
    std::snprintf(where, sizeof where, "patch \"s\" at (u, v) = (%.9g, %.9g)",
                  tess->points[first].x, tess->points[first].y);
    try {
      check_finite(bad, "s", "scene.json");
      ADD_FAILURE() << "no error for point " << k;
    } catch (const DataError& e) {
      EXPECT_EQ(e.source(), "scene.json");
      EXPECT_EQ(e.where(), where) << "point " << k;
      EXPECT_NE(e.message().find("not finite"), std::string::npos) << e.message();
    }
  }
}

}  // namespace
}  // namespace pl
