// curve_joints finds the ends that meet through a grid of cells as wide as its tolerance; here it
// is compared with the comparison of every pair of ends (written out in the test), on curves
// whose ends meet exactly, nearly (inside and just outside the tolerance) and not at all.
#include <gtest/gtest.h>

#include <random>

#include "core/analysis/curve_analysis.hpp"

namespace pl {
namespace {

struct Pair {
  int a, b;
  bool sa, sb;
  bool operator==(const Pair&) const = default;
};

// Every pair of ends within 1e-9 of the curves' size, in the order of a double loop over the ends
// (curve by curve, start before end).
std::vector<Pair> all_pairs(const std::vector<SceneCurve>& curves) {
  const double tol = 1e-9 * curves_size(curves);
  struct End {
    int curve;
    bool start;
    Vec3 p;
  };
  std::vector<End> ends;
  for (std::size_t i = 0; i < curves.size(); ++i) {
    ends.push_back({int(i), true, curves[i].points.front()});
    ends.push_back({int(i), false, curves[i].points.back()});
  }
  std::vector<Pair> r;
  for (std::size_t i = 0; i < ends.size(); ++i)
    for (std::size_t j = i + 1; j < ends.size(); ++j)
      if (glm::length(ends[i].p - ends[j].p) <= tol &&
          !(ends[i].curve == ends[j].curve && ends[i].start == ends[j].start))
        r.push_back({ends[i].curve, ends[j].curve, ends[i].start, ends[j].start});
  return r;
}

SceneCurve cubic(Vec3 a, Vec3 b, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1, 1);
  SceneCurve c;
  c.type = CurveType::Bezier;
  c.points = {a, a + Vec3(u(rng), u(rng), u(rng)), b + Vec3(u(rng), u(rng), u(rng)), b};
  return c;
}

TEST(CurveJointsGrid, FindsThePairsEveryComparisonFinds) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0, 100);
  std::uniform_int_distribution<int> pick(0, 5);
  std::vector<SceneCurve> curves;
  // Chains, stars and loose ends; an end placed near an earlier one at a distance of 0, a tenth,
  // 0.999, 1.001 or ten times the tolerance (the box is about 170 wide: tolerance 1.7e-7).
  const double tol_guess = 1e-9 * std::sqrt(3.0) * 100;
  std::vector<Vec3> placed;
  for (int i = 0; i < 400; ++i) {
    Vec3 a(u(rng), u(rng), u(rng)), b(u(rng), u(rng), u(rng));
    if (!placed.empty() && pick(rng) < 4) {
      const Vec3 base =
          placed[std::uniform_int_distribution<std::size_t>(0, placed.size() - 1)(rng)];
      const double f[] = {0, 0.1, 0.999, 1.001, 10, 0};
      Vec3 dir(u(rng) - 50, u(rng) - 50, u(rng) - 50);
      dir /= glm::length(dir);
      a = base + f[pick(rng)] * tol_guess * dir;
    }
    curves.push_back(cubic(a, b, rng));
    placed.push_back(a);
    placed.push_back(b);
  }
  // A closed curve and two curves on top of each other.
  curves.push_back(cubic(Vec3(5), Vec3(5), rng));
  curves.push_back(curves[3]);
  const std::vector<Pair> expected = all_pairs(curves);
  ASSERT_GT(expected.size(), 100u);
  std::vector<Pair> found;
  for (const JointReport& j : curve_joints(curves))
    found.push_back({j.curves[0], j.curves[1], j.at_start[0], j.at_start[1]});
  EXPECT_EQ(found, expected);
}

TEST(CurveJointsGrid, CurvesFarFromTheOriginAndAllAtOnePoint) {
  std::mt19937 rng(3);
  std::vector<SceneCurve> curves;
  // A chain of unit curves a trillion units from the origin: cells count from the box's corner.
  for (int i = 0; i < 50; ++i)
    curves.push_back(cubic(Vec3(1e12 + i, 0, 0), Vec3(1e12 + i + 1, 0, 0), rng));
  EXPECT_EQ(curve_joints(curves).size(), 49u);
  // Every curve shrunk to one point (size 0, tolerance 0): every pair of ends meets.
  std::vector<SceneCurve> point;
  for (int i = 0; i < 4; ++i) {
    SceneCurve c;
    c.type = CurveType::Bezier;
    c.points.assign(4, Vec3(1, 2, 3));
    point.push_back(c);
  }
  EXPECT_EQ(curve_joints(point).size(), all_pairs(point).size());
  EXPECT_EQ(all_pairs(point).size(), 8u * 7 / 2);
}

}  // namespace
}  // namespace pl
