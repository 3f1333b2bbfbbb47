// The GB patch against the independent reference evaluations (transfinite) in
// tests/data/gb: every sample to 1e-12 of the model's size, domain vertices bit for bit.
#include <gtest/gtest.h>

#include "gb_test_util.hpp"

namespace pl {
namespace {

TEST(GBReference, EverySampleAgrees) {
  PATCHLAB_REQUIRE_GB_REFERENCE();
  for (const std::string& name : test::gb_reference_models()) {
    const GBPatch patch = read_gbp(test::gb_reference_dir() / (name + ".gbp"));
    const auto samples = test::read_gb_samples(test::gb_reference_dir() / (name + ".samples.txt"));
    const int n = patch.sides();
    ASSERT_EQ(samples.size(), static_cast<std::size_t>(n + 1 + 11 * n + 300)) << name;
    for (int i = 0; i < n; ++i) {  // our regular domain is transfinite's, bit for bit
      EXPECT_EQ(patch.polygon().vertex(i).x, samples[i].x.x) << name << " vertex " << i;
      EXPECT_EQ(patch.polygon().vertex(i).y, samples[i].x.y) << name << " vertex " << i;
    }
    const double diag = test::bbox_diagonal(patch.control_points());
    double worst = 0;
    for (const auto& s : samples) {
      const SurfaceJet S = patch.evaluate(s.x);
      worst = std::max(worst, glm::length(S.p - s.p) / diag);
      ASSERT_TRUE(std::isfinite(S.p.x + S.su.x + S.sv.y + S.suu.z + S.suv.x + S.svv.y)) << name;
    }
    EXPECT_LT(worst, 1e-12) << name;
    std::printf("[ reference ] %-9s max error %.3g (relative to diagonal %.4g)\n", name.c_str(),
                worst, diag);
  }
}

}  // namespace
}  // namespace pl
