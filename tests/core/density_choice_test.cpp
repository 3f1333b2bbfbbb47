// Densities per surface from sizes on screen within a triangle budget.
#include "core/eval/density_choice.hpp"

#include <gtest/gtest.h>

#include "core/patch/bezier_patch.hpp"

namespace pl {
namespace {

double total(std::span<const SurfaceSize> sizes, const std::vector<int>& d) {
  double t = 0;
  for (std::size_t i = 0; i < sizes.size(); ++i) {
    const double r = double(d[i]) / sizes[i].density;
    t += sizes[i].triangles * r * r;
  }
  return t;
}

TEST(DensityChoice, LevelsHalveFromTheMaximum) {
  EXPECT_EQ(density_levels({2, 48, 6, 1000}), (std::vector<int>{48, 24, 12, 6, 3}));
  EXPECT_EQ(density_levels({1, 16, 6, 1000}), (std::vector<int>{16, 8, 4, 2, 1}));
  EXPECT_EQ(density_levels({5, 4, 6, 1000}), (std::vector<int>{4}));  // never empty
}

TEST(DensityChoice, SizeOnScreenPicksTheLevelAndTheBudgetLowersTheFinest) {
  const DensityBudget budget{2, 48, 6, 100000};
  // A quad at density 8 has 2 * 8^2 = 128 triangles.
  std::vector<SurfaceSize> sizes{{600, 128, 8}, {100, 128, 8}, {10, 128, 8}, {0, 128, 8}};
  std::vector<int> d = choose_densities(sizes, budget);
  // 600 px / 6 = 100 > 48: the maximum; 100 / 6 = 16.7: 24; 10 / 6: 3 (the coarsest level).
  EXPECT_EQ(d, (std::vector<int>{48, 24, 3, 3}));
  EXPECT_LE(total(sizes, d), 100000.0);
  // A budget of 3,000 triangles: the finest go down first, level by level.
  d = choose_densities(sizes, {2, 48, 6, 3000});
  EXPECT_LE(total(sizes, d), 3000.0);
  EXPECT_EQ(d, (std::vector<int>{24, 24, 3, 3}));
  // Impossible budgets stop at the coarsest level.
  d = choose_densities(sizes, {2, 48, 6, 1});
  EXPECT_EQ(d, (std::vector<int>(4, 3)));
}

TEST(DensityChoice, ASurfaceOneLevelFinerThanNeededKeepsItsDensity) {
  const DensityBudget budget{2, 48, 6, 1000000};
  // 100 px asks for 24; already at 48 it stays, at 12 it goes up to 24.
  std::vector<SurfaceSize> sizes{{100, 2 * 48 * 48, 48}, {100, 2 * 12 * 12, 12}};
  EXPECT_EQ(choose_densities(sizes, budget), (std::vector<int>{48, 24}));
  // Two levels finer than needed: it comes down.
  sizes[0].pixels = 30;  // asks for 6
  EXPECT_EQ(choose_densities(sizes, budget)[0], 6);
  // A density not chosen from the size (a uniform start) goes to what the size asks for.
  sizes[0] = {100, 2 * 48 * 48, 48, false};
  EXPECT_EQ(choose_densities(sizes, budget)[0], 24);
}

TEST(DensityChoice, UniformDensityFitsTheBudget) {
  std::vector<SurfaceSize> sizes(1536, SurfaceSize{0, 2 * 16 * 16, 16});
  // 1536 quads: 2 * 1536 * d^2 <= 600,000 allows d <= 13.97: the level 12.
  EXPECT_EQ(uniform_density(sizes, {2, 48, 6, 600000}), 12);
  EXPECT_EQ(uniform_density(sizes, {2, 48, 6, 100000000}), 48);
  EXPECT_EQ(uniform_density(sizes, {2, 48, 6, 10}), 3);
}

TEST(DensityChoice, BoundingSphereContainsTheControlPoints) {
  std::vector<Vec3> pts;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) pts.push_back(Vec3(i, 2 * j, i * j));
  const BezierPatch patch(3, 3, pts);
  const Sphere s = bounding_sphere(patch);
  for (const Vec3& p : pts) EXPECT_LE(glm::length(p - s.centre), s.radius + 1e-12);
  EXPECT_EQ(s.centre, Vec3(1.5, 3, 2.25));
}

}  // namespace
}  // namespace pl
