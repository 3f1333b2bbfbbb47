#include "core/math/bernstein.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace pl {
namespace {

TEST(Bernstein, PartitionOfUnityAndClosedForm) {
  for (int n = 0; n <= 12; ++n)
    for (double t : {0.0, 0.1, 0.37, 0.5, 0.9, 1.0}) {
      std::vector<double> b(n + 1);
      bernstein_all(n, t, b);
      double sum = 0;
      for (int i = 0; i <= n; ++i) {
        const double closed = binomial(n, i) * std::pow(t, i) * std::pow(1 - t, n - i);
        EXPECT_NEAR(b[i], closed, 1e-15) << "n=" << n << " i=" << i << " t=" << t;
        sum += b[i];
      }
      EXPECT_NEAR(sum, 1.0, 1e-15);
    }
}

TEST(Bernstein, DerivativesMatchFiniteDifferences) {
  const double h = 1e-5;
  for (int n = 1; n <= 8; ++n)
    for (double t : {0.2, 0.5, 0.83}) {
      std::vector<double> d0(n + 1), d1(n + 1), d2(n + 1), p(n + 1), m(n + 1), c(n + 1);
      bernstein_all_d2(n, t, d0, d1, d2);
      bernstein_all(n, t + h, p);
      bernstein_all(n, t - h, m);
      bernstein_all(n, t, c);
      for (int i = 0; i <= n; ++i) {
        EXPECT_NEAR(d1[i], (p[i] - m[i]) / (2 * h), 1e-8);
        EXPECT_NEAR(d2[i], (p[i] - 2 * c[i] + m[i]) / (h * h), 1e-4);
        // The jet form must agree with the array form exactly enough.
        const Jet j = bernstein(n, i, Jet::u(t));
        EXPECT_NEAR(j.f, d0[i], 1e-14);
        EXPECT_NEAR(j.fu, d1[i], 1e-12);
        EXPECT_NEAR(j.fuu, d2[i], 1e-10);
      }
    }
}

TEST(Jet, QuotientRuleMatchesAnalyticDerivatives) {
  // f(u, v) = u v / (u + v): fu = v^2/(u+v)^2, fuu = -2 v^2/(u+v)^3, fuv = 2uv/(u+v)^3.
  const double u = 0.3, v = 0.7;
  const Jet U = Jet::u(u), V = Jet::v(v);
  const Jet f = U * V / (U + V);
  const double s = u + v;
  EXPECT_NEAR(f.f, u * v / s, 1e-15);
  EXPECT_NEAR(f.fu, v * v / (s * s), 1e-15);
  EXPECT_NEAR(f.fv, u * u / (s * s), 1e-15);
  EXPECT_NEAR(f.fuu, -2 * v * v / (s * s * s), 1e-14);
  EXPECT_NEAR(f.fvv, -2 * u * u / (s * s * s), 1e-14);
  EXPECT_NEAR(f.fuv, 2 * u * v / (s * s * s), 1e-14);
}

}  // namespace
}  // namespace pl
