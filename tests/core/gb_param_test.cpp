// The building blocks of GB patches: Bernstein tables and the polygon's local parameters
// (Wachspress and mean value coordinates, s_i, h_i) against their defining properties and
// finite differences.
#include <gtest/gtest.h>

#include <random>

#include "core/domain/convex_polygon.hpp"
#include "core/math/bernstein_jets.hpp"
#include "core/param/mean_value.hpp"
#include "core/param/wachspress.hpp"

namespace pl {
namespace {

TEST(GBParam, BernsteinTableMatchesBernsteinAll) {
  for (int d = 0; d <= 20; ++d)
    for (double t : {0.0, 0.13, 0.5, 0.77, 1.0}) {
      double e0[64], e1[64], e2[64];
      bernstein_all_d2(d, t, e0, e1, e2);
      const BernsteinTable b(d, t);
      for (int j = 0; j <= d; ++j) {
        EXPECT_NEAR(b.d0[j], e0[j], 1e-14) << d << " " << j;
        EXPECT_NEAR(b.d1[j], e1[j], 1e-12 * (1 + d * d)) << d << " " << j;
        EXPECT_NEAR(b.d2[j], e2[j], 1e-11 * (1 + d * d * d)) << d << " " << j;
        const Jet one = bernstein_jet(d, j, Jet::u(t));
        EXPECT_NEAR(one.f, e0[j], 1e-14);
        EXPECT_NEAR(one.fu, e1[j], 1e-12 * (1 + d * d));
        EXPECT_NEAR(one.fuu, e2[j], 1e-11 * (1 + d * d * d));
      }
    }
}

// The properties every parameterization has (parameterization.hpp), through the interface:
// partition of unity, linear reproduction, s_i and h_i against their definitions, second
// derivatives against differences of the first, the Lagrange property at the vertices and
// s_i = t, h_i = 0 along side i. xs: interior points; positive: the coordinates are > 0 there.
void check_parameterization(const Parameterization& par, const std::vector<Vec2>& xs,
                            bool positive) {
  const int n = par.sides();
  std::vector<Jet> lam(n), s(n), h(n);
  for (const Vec2& x : xs) {
    par.evaluate(x, lam, s, h);
    Jet sum;
    Vec2 rep(0);
    for (int i = 0; i < n; ++i) {
      sum += lam[i];
      rep += lam[i].f * par.vertex(i);
      if (positive) {
        EXPECT_GT(lam[i].f, 0);
      }
    }
    EXPECT_NEAR(sum.f, 1, 1e-14);  // partition of unity, with vanishing derivatives
    EXPECT_NEAR(sum.fu, 0, 1e-13);
    EXPECT_NEAR(sum.fuv, 0, 1e-12);
    EXPECT_NEAR(rep.x, x.x, 1e-14);  // linear reproduction
    EXPECT_NEAR(rep.y, x.y, 1e-14);
    for (int i = 0; i < n; ++i) {
      const Jet& a = lam[(i + n - 1) % n];
      const Jet& b = lam[i];
      const Jet s_def = b / (a + b);  // the definition, fine away from the far sides
      EXPECT_NEAR(s[i].f, s_def.f, 1e-12);
      EXPECT_NEAR(s[i].fu, s_def.fu, 1e-10 * (1 + std::fabs(s_def.fu)));
      EXPECT_NEAR(s[i].fvv, s_def.fvv, 1e-9 * (1 + std::fabs(s_def.fvv)));
      EXPECT_NEAR(h[i].f, 1 - a.f - b.f, 1e-14);
      EXPECT_NEAR(h[i].fuu, -a.fuu - b.fuu, 1e-11);
    }
    // Second derivatives of lambda_0 against central differences of the first ones.
    const double e = 1e-6;
    std::vector<Jet> lp(n), lm(n);
    par.evaluate(x + Vec2(e, 0), lp, {}, {});
    par.evaluate(x - Vec2(e, 0), lm, {}, {});
    EXPECT_NEAR(lam[0].fuu, (lp[0].fu - lm[0].fu) / (2 * e), 1e-6);
    EXPECT_NEAR(lam[0].fuv, (lp[0].fv - lm[0].fv) / (2 * e), 1e-6);
    EXPECT_NEAR(lam[0].fu, (lp[0].f - lm[0].f) / (2 * e), 1e-8);
  }
  // Lagrange property next to the vertices (exactly at them for Wachspress); s_i runs 0..1
  // along side i; h_i = 0 on it.
  for (int i = 0; i < n; ++i) {
    const Vec2 near = par.vertex(i) + 1e-13 * (par.vertex(i + 1) - par.vertex(i));
    par.evaluate(near, lam, {}, {});
    for (int j = 0; j < n; ++j) EXPECT_NEAR(lam[j].f, i == j ? 1.0 : 0.0, 1e-12);
    for (double t : {0.1, 0.5, 0.9}) {
      par.evaluate((1 - t) * par.vertex(i - 1) + t * par.vertex(i), {}, s, h);
      EXPECT_NEAR(s[i].f, t, 1e-14);
      EXPECT_NEAR(h[i].f, 0, 1e-15);
      EXPECT_TRUE(std::isfinite(s[i].f + s[i].fuu + s[i].fvv));
    }
  }
}

std::vector<Vec2> random_points(std::size_t count, double radius, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> r(-1, 1);
  std::vector<Vec2> xs;
  while (xs.size() < count) {
    const Vec2 x(r(rng), r(rng));
    if (glm::length(x) < radius) xs.push_back(x);
  }
  return xs;
}

TEST(GBParam, WachspressPropertiesAndSideParameters) {
  for (int n = 3; n <= 12; ++n) {
    const auto dom = ConvexPolygonDomain::regular(n);
    // Inside the incircle of every regular polygon.
    check_parameterization(WachspressParameters(dom.vertices()), random_points(100, 0.45, 5 + n),
                           true);
    // Exactly at a vertex the product form is still defined: Lagrange there too.
    const WachspressParameters par(dom.vertices());
    std::vector<Jet> lam(n);
    for (int i = 0; i < n; ++i) {
      par.evaluate(dom.vertex(i), lam, {}, {});
      for (int j = 0; j < n; ++j) EXPECT_NEAR(lam[j].f, i == j ? 1.0 : 0.0, 1e-15);
    }
  }
}

TEST(GBParam, MeanValuePropertiesAndSideParameters) {
  for (int n = 3; n <= 12; ++n)  // convex: positive coordinates (Floater 2003)
    check_parameterization(MeanValueParameters(ConvexPolygonDomain::regular(n).vertices()),
                           random_points(100, 0.45, 7 + n), true);
  // An L shape (concave): the coordinates may be negative behind the reflex vertex.
  const std::vector<Vec2> L = {{-1, -1}, {1, -1}, {1, 0}, {0, 0}, {0, 1}, {-1, 1}};
  std::vector<Vec2> xs;
  for (const Vec2& x : random_points(400, 2, 11))
    if ((x.x < -0.05 || x.y < -0.05) && x.x > -0.95 && x.x < 0.95 && x.y > -0.95 && x.y < 0.95)
      xs.push_back(x);
  check_parameterization(MeanValueParameters(L), xs, false);
}

TEST(GBParam, SumsOffSideLeaveOutTheSidesEnds) {
  for (int n = 3; n <= 9; ++n) {
    std::vector<Jet> v(n), out(n);
    for (int j = 0; j < n; ++j) v[j] = Jet(std::ldexp(1.0, j));  // sums are exact and unique
    sums_off_side<16>(n, v.data(), out.data(), kAllSides, Jet(0.0));
    for (int i = 0; i < n; ++i) {
      double expected = 0;
      for (int j = 0; j < n; ++j)
        if (j != i && j != (i + n - 1) % n) expected += v[j].f;
      EXPECT_EQ(out[i].f, expected) << n << " " << i;
    }
  }
}

}  // namespace
}  // namespace pl
