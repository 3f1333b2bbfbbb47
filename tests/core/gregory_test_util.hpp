// Helpers of the Gregory patch tests.
#pragma once

#include <gtest/gtest.h>

#include <cmath>

#include "core/patch/patch.hpp"
#include "test_util.hpp"

namespace pl::test {

inline bool finite_vec(const Vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
inline bool finite_jet(const SurfaceJet& s) {
  return finite_vec(s.p) && finite_vec(s.su) && finite_vec(s.sv) && finite_vec(s.suu) &&
         finite_vec(s.suv) && finite_vec(s.svv);
}
inline double jet_distance(const SurfaceJet& a, const SurfaceJet& b) {
  return std::max({max_abs(a.p - b.p), max_abs(a.su - b.su), max_abs(a.sv - b.sv),
                   max_abs(a.suu - b.suu), max_abs(a.suv - b.suv), max_abs(a.svv - b.svv)});
}

// Exact derivatives against central differences at an interior point x (step h).
inline void expect_matches_finite_differences(const Patch& p, Vec2 x) {
  const SurfaceJet s = p.evaluate(x);
  const FiniteDifferences d1 = finite_differences(p, x, 1e-5);
  const FiniteDifferences d2 = finite_differences(p, x, 1e-4);
  EXPECT_LT(max_abs(s.su - d1.su), 1e-7) << x.x << " " << x.y;
  EXPECT_LT(max_abs(s.sv - d1.sv), 1e-7) << x.x << " " << x.y;
  EXPECT_LT(max_abs(s.suu - d2.suu), 1e-5) << x.x << " " << x.y;
  EXPECT_LT(max_abs(s.suv - d2.suv), 1e-5) << x.x << " " << x.y;
  EXPECT_LT(max_abs(s.svv - d2.svv), 1e-5) << x.x << " " << x.y;
}

// The basis is a partition of unity: sum phi_k = 1 with vanishing derivatives.
inline void expect_partition_of_unity(const Patch& p, Vec2 x) {
  std::vector<Jet> phi(p.size());
  p.basis(x, phi);
  Jet sum;
  for (const Jet& w : phi) sum += w;
  EXPECT_NEAR(sum.f, 1, 1e-14);
  for (double d : {sum.fu, sum.fv, sum.fuu, sum.fuv, sum.fvv}) EXPECT_NEAR(d, 0, 1e-12);
}

}  // namespace pl::test
