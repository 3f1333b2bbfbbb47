// The batched differential geometry (several samples per SIMD register) against the one-sample
// form: the same operations in the same order, so the same numbers, singular samples included.
#include <gtest/gtest.h>

#include <random>

#include "core/geometry/differential_geometry.hpp"

namespace pl {
namespace {

std::vector<SurfaceJet> sample_jets(unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> r(-3, 3);
  const auto v = [&] { return Vec3(r(rng), r(rng), r(rng)); };
  std::vector<SurfaceJet> jets;
  for (int i = 0; i < 1001; ++i) {  // not a multiple of any lane count
    SurfaceJet s{v(), v(), v(), v(), v(), v()};
    switch (i % 7) {
      case 1:  // degenerate: Su parallel to Sv
        s.sv = -2.5 * s.su;
        break;
      case 2:  // collapsed: Su = 0
        s.su = Vec3(0);
        break;
      case 3:  // nearly degenerate, just regular
        s.sv = s.su + 1e-9 * v();
        break;
      case 4:  // umbilic-like: zero second derivatives
        s.suu = s.suv = s.svv = Vec3(0);
        break;
      case 5:  // non-finite
        s.su.x = std::numeric_limits<double>::infinity();
        break;
      default:
        break;
    }
    jets.push_back(s);
  }
  return jets;
}

void expect_same(const SurfaceGeometry& a, const SurfaceGeometry& b, std::size_t i) {
  EXPECT_EQ(a.status, b.status) << i;
  EXPECT_EQ(a.normal, b.normal) << i;
  EXPECT_EQ(a.gaussian, b.gaussian) << i;
  EXPECT_EQ(a.mean, b.mean) << i;
  EXPECT_EQ(a.kmin, b.kmin) << i;
  EXPECT_EQ(a.kmax, b.kmax) << i;
}

TEST(GeometryBatch, EqualsTheOneSampleFormBitForBit) {
  const auto jets = sample_jets(5);
  std::vector<SurfaceGeometry> many(jets.size());
  differential_geometry_many(jets, many);
  int singular = 0;
  for (std::size_t i = 0; i < jets.size(); ++i) {
    expect_same(many[i], differential_geometry(jets[i]), i);
    singular += many[i].status == GeometryStatus::Singular;
  }
  EXPECT_GT(singular, 3 * 1001 / 7 - 3);  // the degenerate, collapsed and non-finite ones
}

TEST(GeometryBatch, IndexedFormTouchesOnlyTheListedSamples) {
  const auto jets = sample_jets(6);
  std::vector<uint32_t> index;
  for (uint32_t i = 3; i < jets.size(); i += 3) index.push_back(i);
  SurfaceGeometry marker;
  marker.mean = 42;
  std::vector<SurfaceGeometry> out(jets.size(), marker);
  differential_geometry_many(jets, index, out);
  for (std::size_t i = 0; i < jets.size(); ++i) {
    if (i >= 3 && i % 3 == 0)
      expect_same(out[i], differential_geometry(jets[i]), i);
    else
      EXPECT_EQ(out[i].mean, 42) << i;
  }
}

}  // namespace
}  // namespace pl
