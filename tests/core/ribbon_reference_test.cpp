// The ribbon-based schemes against the research library's samples in tests/data/schemes (README
// there): with the library's forward-difference twists every sample to 1e-12 of the face's size;
// with exact twists within the size of that estimate's error (the side-based scheme, which has no
// twists, to 1e-12 as well).
#include <gtest/gtest.h>

#include <cstdio>

#include "ribbon_test_util.hpp"

namespace pl {
namespace {

using transfinite::RibbonScheme;
using transfinite::TwistEstimate;

struct Match {
  double worst = 0;  // largest distance / face size
  double worst_abs = 0;
};

Match match(RibbonScheme scheme, int n, TwistEstimate twists) {
  const std::string name = std::string(transfinite::ribbon_scheme_name(scheme));
  const auto sides = test::read_reference_face(test::scheme_reference_dir() / "faces" /
                                               ("face" + std::to_string(n) + ".txt"));
  const auto samples = test::read_scheme_samples(
      test::scheme_reference_dir() / (name + "-face" + std::to_string(n) + ".samples.txt"));
  EXPECT_EQ(samples.size(), std::size_t(12 * n + 301)) << name << " face" << n;
  RibbonPatchOptions options;
  options.twists = twists;
  if (scheme == RibbonScheme::SideBased) {  // its domain comes from the curves: take the file's
    std::vector<Vec2> v;
    for (int i = 0; i < n; ++i) v.push_back(samples[std::size_t(i)].x);
    options.domain = v;
  }
  const RibbonPatch patch(scheme, sides, options);
  if (scheme != RibbonScheme::SideBased)
    for (int i = 0; i < n; ++i) {  // the regular n-gon is the library's, bit for bit
      EXPECT_EQ(patch.polygon().vertex(i).x, samples[std::size_t(i)].x.x) << name << " " << i;
      EXPECT_EQ(patch.polygon().vertex(i).y, samples[std::size_t(i)].x.y) << name << " " << i;
    }
  const double diag = test::points_diagonal(sides);
  Match m;
  for (const auto& s : samples) {
    const SurfaceJet S = patch.evaluate(s.x);
    EXPECT_TRUE(std::isfinite(S.p.x + S.su.x + S.sv.y + S.suu.z + S.suv.x + S.svv.y))
        << name << " face" << n << " at " << s.x.x << ", " << s.x.y;
    const double e = glm::length(S.p - s.p);
    m.worst_abs = std::max(m.worst_abs, e);
    m.worst = std::max(m.worst, e / diag);
  }
  return m;
}

TEST(RibbonReference, EverySampleWithTheLibrarysTwistEstimate) {
  for (RibbonScheme scheme : transfinite::all_ribbon_schemes())
    for (int n = 3; n <= 6; ++n) {
      const Match m = match(scheme, n, TwistEstimate::ForwardDifference);
      EXPECT_LT(m.worst, 1e-12) << transfinite::ribbon_scheme_name(scheme) << " face" << n;
      std::printf(
          "[ reference ] %-18s face%d  forward-difference twists: max error %.3g relative\n",
          std::string(transfinite::ribbon_scheme_name(scheme)).c_str(), n, m.worst);
    }
}

TEST(RibbonReference, EverySampleWithExactTwists) {
  for (RibbonScheme scheme : transfinite::all_ribbon_schemes())
    for (int n = 3; n <= 6; ++n) {
      const Match m = match(scheme, n, TwistEstimate::Exact);
      if (scheme == RibbonScheme::SideBased)
        EXPECT_LT(m.worst, 1e-12) << "face" << n;  // no twists: the same numbers
      else  // the estimate's own error: up to 1.4e-4 on these faces (coordinates up to ~11)
        EXPECT_LT(m.worst_abs, 1.5e-4) << transfinite::ribbon_scheme_name(scheme) << " face" << n;
      std::printf("[ reference ] %-18s face%d  exact twists: max distance %.3g (%.3g relative)\n",
                  std::string(transfinite::ribbon_scheme_name(scheme)).c_str(), n, m.worst_abs,
                  m.worst);
    }
}

}  // namespace
}  // namespace pl
