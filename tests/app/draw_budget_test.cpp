#include "app/editor/logic/draw_budget.hpp"

#include <gtest/gtest.h>

namespace pl {
namespace {

void frames(DrawBudget& b, int n, double ms, bool moving = true) {
  for (int i = 0; i < n; ++i) b.frame(ms, moving);
}

TEST(DrawBudget, SlowMovingFramesStepTheScaleDownToTheSmallest) {
  DrawBudget b(33);
  EXPECT_EQ(b.scale(), 1.0);
  EXPECT_TRUE(b.note().empty());
  frames(b, DrawBudget::kWindow - 1, 60);
  EXPECT_EQ(b.scale(), 1.0) << "a step needs a window of frames";
  frames(b, 1, 60);
  EXPECT_EQ(b.scale(), 0.75);
  EXPECT_EQ(b.note(), "view at 75 % while moving");
  frames(b, DrawBudget::kWindow, 60);
  EXPECT_EQ(b.scale(), 0.5);
  frames(b, 4 * DrawBudget::kWindow, 60);
  EXPECT_EQ(b.scale(), DrawBudget::kScales.back());
}

TEST(DrawBudget, OneSlowFrameAmongFastOnesChangesNothing) {
  DrawBudget b(33);
  for (int i = 0; i < 20; ++i) b.frame(i % 5 == 2 ? 200 : 10, true);
  EXPECT_EQ(b.scale(), 1.0);
}

TEST(DrawBudget, FastFramesStepBackUpWhereTheLargerScaleFits) {
  DrawBudget b(33);
  frames(b, 2 * DrawBudget::kWindow, 60);
  ASSERT_EQ(b.scale(), 0.5);
  // 20 ms at half scale would be about 45 ms at 0.75: over the budget, so it stays.
  frames(b, 3 * DrawBudget::kWindow, 20);
  EXPECT_EQ(b.scale(), 0.5);
  // 10 ms: 22.5 ms at 0.75 and 17.8 ms back at full scale fit.
  frames(b, DrawBudget::kWindow, 10);
  EXPECT_EQ(b.scale(), 0.75);
  frames(b, DrawBudget::kWindow, 10);
  EXPECT_EQ(b.scale(), 1.0);
}

TEST(DrawBudget, AtRestTheViewIsAtFullResolutionAtOnce) {
  DrawBudget b(33);
  frames(b, 3 * DrawBudget::kWindow, 80);
  ASSERT_LT(b.scale(), 1.0);
  b.frame(80, false);
  EXPECT_EQ(b.scale(), 1.0);
  EXPECT_TRUE(b.note().empty());
  frames(b, DrawBudget::kWindow - 1, 80);
  EXPECT_EQ(b.scale(), 1.0) << "a new movement starts a new window";
}

}  // namespace
}  // namespace pl
