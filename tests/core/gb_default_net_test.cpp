// Default control nets of the convex GB patch (core/patch/gb/default_net.hpp), and planar
// reproduction of GB nets, checked against independent computations: the plane equation,
// tensor-product Bézier nets built from closed-form Coons-type surfaces, BezierPatch evaluation.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <string>

#include "core/patch/bezier_patch.hpp"
#include "core/patch/gb/default_net.hpp"
#include "gb_domain_samples.hpp"
#include "gb_test_util.hpp"
#include "test_util.hpp"

namespace pl {
namespace {

// Random interior points, points on every side (vertices included) and the centre: every kind
// of place the patch is evaluated at.
std::vector<Vec2> domain_samples(const ConvexPolygonDomain& dom, int interior, unsigned seed) {
  std::vector<Vec2> out = test::polygon_interior(dom, interior, seed, 1e-4);
  for (Vec2 x : test::polygon_sides(dom, 8)) out.push_back(x);
  out.push_back({0, 0});
  return out;
}

struct Plane {
  Vec3 origin, normal;  // unit normal
  double distance(const Vec3& p) const { return glm::dot(p - origin, normal); }
  Vec3 project(const Vec3& p) const { return p - distance(p) * normal; }
};

Plane random_plane(unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> r(-1, 1);
  const Vec3 nrm = glm::normalize(Vec3(r(rng), r(rng), r(rng)));
  return {Vec3(3 * r(rng), 3 * r(rng), 3 * r(rng)), nrm};
}

// Angle (radians) between the surface normal Su x Sv and the plane normal, up to orientation.
double normal_angle(const SurfaceJet& s, const Vec3& normal) {
  const Vec3 c = glm::cross(s.su, s.sv);
  return std::asin(std::min(1.0, glm::length(glm::cross(glm::normalize(c), normal))));
}

// A random Bézier control polygon of degree d.
std::vector<Vec3> random_polygon(int d, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> r(-2, 2);
  std::vector<Vec3> p(d + 1);
  for (Vec3& q : p) q = {r(rng), r(rng), r(rng)};
  return p;
}

// The degree-(d,d) net Q[a][b] of S(u,v) = f(u) + v g(u) + h(v) + u k(v): v g(u) is linear in v,
// whose degree-d form has the control points (b/d) g_a; likewise for u k(v). With coons = false
// only the translational part f(u) + h(v).
std::vector<std::vector<Vec3>> coons_net(int d, unsigned seed, bool coons) {
  std::mt19937_64 rng(seed);
  const auto f = random_polygon(d, rng), g = random_polygon(d, rng), h = random_polygon(d, rng),
             k = random_polygon(d, rng);
  std::vector<std::vector<Vec3>> q(d + 1, std::vector<Vec3>(d + 1));
  for (int a = 0; a <= d; ++a)
    for (int b = 0; b <= d; ++b) {
      q[a][b] = f[a] + h[b] + Vec3(4.0 * a, 4.0 * b, 0);  // spread over the plane a little
      if (coons) q[a][b] += (double(b) / d) * g[a] + (double(a) / d) * k[b];
    }
  return q;
}

// The GB net of a tensor-product net (the README of the reference folder maps sides to rows).
GBPatch gb_of_grid(const std::vector<std::vector<Vec3>>& q) {
  const int d = static_cast<int>(q.size()) - 1;
  std::vector<Vec3> p(GBPatch::point_count(4, d));
  const GBPatch shape(4, d, p);
  for (int k = 0; k < shape.layers(); ++k)
    for (int j = 0; j <= d; ++j) {
      p[shape.index(0, j, k)] = q[d - k][j];
      p[shape.index(1, j, k)] = q[d - j][d - k];
      p[shape.index(2, j, k)] = q[k][d - j];
      p[shape.index(3, j, k)] = q[j][k];
    }
  if (d % 2 == 0) p[0] = q[d / 2][d / 2];
  return GBPatch(4, d, std::move(p));
}

BezierPatch bezier_of_grid(const std::vector<std::vector<Vec3>>& q) {
  const int d = static_cast<int>(q.size()) - 1;
  std::vector<Vec3> pts;
  for (int a = 0; a <= d; ++a)
    for (int b = 0; b <= d; ++b) pts.push_back(q[a][b]);
  return BezierPatch(d, d, std::move(pts));
}

// Every point of rings >= kept (and C_0 where it matters) is the grid's, and the patch is the
// tensor-product patch of the grid. Returns the largest relative deviation of points and
// surface samples; `compared` (if given) counts the defaulted points that were compared.
double reproduction_error(const std::vector<std::vector<Vec3>>& q, int kept,
                          int* compared = nullptr) {
  const int d = static_cast<int>(q.size()) - 1;
  const GBPatch truth = gb_of_grid(q);
  const GBPatch def = gb_default_net(truth, kept);
  std::vector<Vec3> all;
  for (const auto& row : q) all.insert(all.end(), row.begin(), row.end());
  const double scale = test::bbox_diagonal(all);
  double worst = 0;
  // For odd d, C_0 has no weight for n = 4: it is not a point of the grid.
  for (std::size_t k = (d % 2 == 0 ? 0 : 1); k < truth.size(); ++k) {
    worst = std::max(worst, test::max_abs(def.control_point(k) - truth.control_point(k)) / scale);
    if (compared && (k == 0 || gb_ring(4, d, k) >= kept)) ++*compared;
  }
  const BezierPatch tp = bezier_of_grid(q);
  for (Vec2 x : domain_samples(def.polygon(), 60, 5)) {
    const Vec3 t = tp.evaluate({(x.x + 1) / 2, (x.y + 1) / 2}).p;
    worst = std::max(worst, test::max_abs(def.evaluate(x).p - t) / scale);
  }
  return worst;
}

TEST(GBDefaultNet, RingsNumberTheStoredPoints) {
  for (int n = 3; n <= 12; ++n)
    for (int d = 1; d <= 7; ++d) {
      const GBPatch g(n, d, std::vector<Vec3>(GBPatch::point_count(n, d)));
      EXPECT_EQ(gb_ring(n, d, 0), -1);
      for (int k = 0; k < g.layers(); ++k)
        for (int i = 0; i < n; ++i)
          for (int j = k; j <= d - 1 - k; ++j) ASSERT_EQ(gb_ring(n, d, g.index(i, j, k)), k);
      // A grid position's ring is its distance to the nearest side of the grid.
      for (int i = 0; i < n; ++i)
        for (int k = 0; k < g.layers(); ++k)
          for (int j = 0; j <= d; ++j)
            ASSERT_EQ(gb_ring(n, d, g.index(i, j, k)), std::min({j, k, d - j}));
      EXPECT_THROW(gb_ring(n, d, g.size()), std::invalid_argument);
    }
}

TEST(GBDefaultNet, PlanarDataGivesThePlane) {
  double worst_point = 0, worst_sample = 0, worst_angle = 0;
  for (int n = 3; n <= 12; ++n)
    for (int d = 2; d <= 7; ++d)
      for (int kept = 1; kept <= 2; ++kept) {
        const Plane plane = random_plane(100 * n + 10 * d + kept);
        std::vector<Vec3> p = test::random_gb(n, d, n + d).control_points();
        for (Vec3& q : p) q = plane.project(q);
        // Off-plane junk where the defaults go: it must not survive.
        for (std::size_t k = 0; k < p.size(); ++k)
          if (k == 0 || gb_ring(n, d, k) >= kept) p[k] += 5.0 * plane.normal;
        const GBPatch def = gb_default_net(GBPatch(n, d, p), kept);
        const double scale = test::bbox_diagonal(def.control_points());
        for (const Vec3& q : def.control_points()) {
          ASSERT_TRUE(std::isfinite(q.x + q.y + q.z)) << n << " " << d;
          worst_point = std::max(worst_point, std::fabs(plane.distance(q)) / scale);
        }
        for (Vec2 x : domain_samples(def.polygon(), 40, n * d)) {
          const SurfaceJet s = def.evaluate(x);
          worst_sample = std::max(worst_sample, std::fabs(plane.distance(s.p)) / scale);
          worst_angle = std::max(worst_angle, normal_angle(s, plane.normal));
        }
        ASSERT_LT(worst_point, 1e-12) << "n=" << n << " d=" << d << " kept rings " << kept;
        ASSERT_LT(worst_sample, 1e-12) << "n=" << n << " d=" << d << " kept rings " << kept;
        ASSERT_LT(worst_angle, 1e-10) << "n=" << n << " d=" << d << " kept rings " << kept;
      }
  std::printf(
      "[ planar    ] defaults off the plane %.2g, samples %.2g (relative), normal %.2g rad\n",
      worst_point, worst_sample, worst_angle);
}

TEST(GBDefaultNet, FourSidedCoonsNetsAreReproducedFromRings0And1) {
  // With rings 0 and 1 kept, d = 2 and 4 default C_0 alone (the even-d Coons stencil, rule 4),
  // d = 3 nothing that has weight (C_0 has none for n = 4, odd d), so it is left out; from d = 5
  // the ring rules 2 (corner blocks) and, for even d, 3 (middle column) place rings 2 .. l-1.
  for (int d : {2, 4, 5, 6, 7, 8, 9}) {
    const auto q = coons_net(d, 40 + d, true);
    int compared = 0;
    const double err = reproduction_error(q, 2, &compared);
    // Rule 2 extrapolates with weights up to j k <= (l-1)^2 = 16 on coordinates ~4 d across,
    // relative to that size: about 16 ulps, so 1e-13 leaves room.
    EXPECT_LT(err, 1e-13) << "d=" << d;
    int expected = d % 2 == 0 ? 1 : 0;  // C_0 of even d, then ring r's 4 (d - 2r) points
    for (int r = 2; r < GBPatch::layers(d); ++r) expected += 4 * (d - 2 * r);
    EXPECT_EQ(compared, expected) << "d=" << d;
    // The data exercise the Boolean sums: plain extrapolation of rows 0 and 1 is far off.
    if (d >= 5) {
      double off = 0;
      for (int a = 2; a <= d - 2; ++a)
        for (int b = 2; b <= d - 2; ++b)
          off = std::max(off, test::max_abs(q[a][b] - (q[a][0] + double(b) * (q[a][1] - q[a][0]))));
      EXPECT_GT(off, 0.1) << "d=" << d;
    }
    std::printf(
        "[ coons     ] d=%d rings 0-1 kept: %d defaulted points compared, largest deviation %.2g "
        "(relative)\n",
        d, compared, err);
  }
}

TEST(GBDefaultNet, FourSidedTranslationalNetsFromTheBoundaryAlone) {
  for (int d = 2; d <= 7; ++d) {
    const double err = reproduction_error(coons_net(d, 60 + d, false), 1);
    EXPECT_LT(err, 1e-12) << "d=" << d;
    std::printf("[ transl.   ] d=%d boundary kept: largest deviation %.2g (relative)\n", d, err);
  }
}

TEST(GBDefaultNet, CubicCentreIsTheMeanOfTheParallelogramTwists) {
  // gb-center's rule for cubic patches, computed here from the boundary points directly.
  for (int n = 3; n <= 8; ++n) {
    const GBPatch g = test::random_gb(n, 3, 70 + n);
    const GBPatch def = gb_default_net(g, 1);
    Vec3 mean(0);
    for (int i = 0; i < n; ++i) {
      const Vec3 twist = g.point(i, 1, 0) + g.point(i - 1, 2, 0) - g.point(i, 0, 0);
      // Two additions on coordinates <= ~6 (ulp 9e-16), in another order than the library's.
      EXPECT_LT(test::max_abs(def.point(i, 1, 1) - twist), 4e-15);
      mean += twist / double(n);
    }
    // The mean of n <= 8 such points, summed in another order.
    EXPECT_LT(test::max_abs(def.control_point(0) - mean), 8e-15);
  }
}

TEST(GBDefaultNet, ReferenceModelsFromRings0And1) {
  // The figures core/patch/gb/default_net.hpp quotes: the default surface from rings 0 and 1 of
  // each designed reference net against that net's samples (transfinite's evaluations of the
  // designed surface), largest distance relative to the net's diagonal.
  PATCHLAB_REQUIRE_GB_REFERENCE();
  // The quoted figures, rounded up in their last digit (tp4-d3: nothing with weight defaulted,
  // so rounding of the evaluation, ~4 ulps relative).
  const std::map<std::string, double> quoted{
      {"cagd86", 0.0055}, {"tp4-d3", 1e-15},    {"tp4-d4", 0.04},    {"tp4-d5", 0.19},
      {"tp4-d6", 0.21},   {"dome3-d3", 0.0033}, {"dome6-d4", 0.043}, {"dome7-d3", 0.025}};
  for (const std::string& name : test::gb_reference_models()) {
    const GBPatch patch = read_gbp(test::gb_reference_dir() / (name + ".gbp"));
    const auto samples = test::read_gb_samples(test::gb_reference_dir() / (name + ".samples.txt"));
    const GBPatch def = gb_default_net(patch, 2);
    const double diag = test::bbox_diagonal(patch.control_points());
    double worst = 0;
    for (const auto& s : samples)
      worst = std::max(worst, glm::length(def.evaluate(s.x).p - s.p) / diag);
    std::printf("[ reference ] %-9s d=%d: defaults from rings 0-1 within %.2g of the design\n",
                name.c_str(), patch.degree(), worst);
    ::testing::Test::RecordProperty("default_vs_" + name, std::to_string(worst));
    EXPECT_LT(worst, quoted.at(name)) << name;
  }
}

TEST(GBDefaultNet, PlacedPointsAreKeptAndTheBoundaryIsRequired) {
  const GBPatch g = test::random_gb(5, 6, 3);
  std::vector<char> flags(g.size());
  for (std::size_t k = 1; k < g.size(); ++k) flags[k] = gb_ring(5, 6, k) == 0 || k % 3 == 0;
  const auto placed = std::make_unique<bool[]>(g.size());
  for (std::size_t k = 0; k < g.size(); ++k) placed[k] = flags[k] != 0;
  const GBPatch def = gb_default_net(g, std::span<const bool>(placed.get(), g.size()));
  int moved = 0;
  for (std::size_t k = 0; k < g.size(); ++k) {
    if (placed[k]) {
      EXPECT_EQ(def.control_point(k), g.control_point(k)) << k;
    }
    moved += def.control_point(k) != g.control_point(k);
  }
  EXPECT_GT(moved, 0);
  placed[1] = false;
  EXPECT_THROW(gb_default_net(g, std::span<const bool>(placed.get(), g.size())),
               std::invalid_argument);
  EXPECT_THROW(gb_default_net(g, std::span<const bool>(placed.get(), g.size() - 1)),
               std::invalid_argument);
  EXPECT_THROW(gb_default_net(g, 0), std::invalid_argument);
}

TEST(GBDefaultNet, FiniteForEverySideCountAndDegree) {
  for (int n = 3; n <= 12; ++n)
    for (int d = 2; d <= 7; ++d)
      for (int kept = 1; kept <= 2; ++kept) {
        const GBPatch def = gb_default_net(test::random_gb(n, d, 90 + n * d), kept);
        for (const Vec3& q : def.control_points())
          ASSERT_TRUE(std::isfinite(q.x + q.y + q.z)) << n << " " << d;
        for (Vec2 x : domain_samples(def.polygon(), 30, d)) {
          const SurfaceJet s = def.evaluate(x);
          const double all = test::max_abs(s.p) + test::max_abs(s.su) + test::max_abs(s.sv) +
                             test::max_abs(s.suu) + test::max_abs(s.suv) + test::max_abs(s.svv);
          ASSERT_TRUE(std::isfinite(all)) << n << " " << d;
        }
      }
}

// A GB patch whose control points all lie on a plane is that plane,
// at corners, sides, the centre and inside, with the plane's normal.
TEST(GBPatchPlanar, RandomPlanarNetsAreThePlane) {
  double worst_sample = 0, worst_angle = 0;
  for (int n = 3; n <= 12; ++n)
    for (int d = 2; d <= 7; ++d) {
      const Plane plane = random_plane(1000 + 10 * n + d);
      std::vector<Vec3> p = test::random_gb(n, d, 7 * n + d).control_points();
      std::mt19937_64 rng(n * 31 + d);
      std::uniform_real_distribution<double> r(-1, 1);
      // Random positions in the plane, not a projection of a tidy layout alone.
      for (Vec3& q : p) q = plane.project(q + Vec3(r(rng), r(rng), r(rng)));
      const GBPatch g(n, d, p);
      const double scale = test::bbox_diagonal(p);
      for (Vec2 x : domain_samples(g.polygon(), 40, 3 * n + d)) {
        const SurfaceJet s = g.evaluate(x);
        worst_sample = std::max(worst_sample, std::fabs(plane.distance(s.p)) / scale);
        worst_angle = std::max(worst_angle, normal_angle(s, plane.normal));
      }
      ASSERT_LT(worst_sample, 1e-12) << "n=" << n << " d=" << d;
      ASSERT_LT(worst_angle, 1e-10) << "n=" << n << " d=" << d;
    }
  std::printf("[ planar    ] samples off the plane %.2g (relative), normal %.2g rad\n",
              worst_sample, worst_angle);
}

}  // namespace
}  // namespace pl
