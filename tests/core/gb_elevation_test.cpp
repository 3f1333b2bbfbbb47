// Degree elevation of the convex GB patch (core/patch/gb/elevation.hpp): whether an exact
// elevation exists (least squares over the basis functions), exactness for n = 4 against an
// independent tensor-product elevation, and what is kept for every n (boundary, tangent planes).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "core/patch/gb/default_net.hpp"
#include "core/patch/gb/elevation.hpp"
#include "gb_domain_samples.hpp"
#include "gb_test_util.hpp"
#include "test_util.hpp"

namespace pl {
namespace {

// Row r: the values of every basis function of the (n, d) patch at xs[r].
Eigen::MatrixXd basis_matrix(int n, int d, const std::vector<Vec2>& xs) {
  const GBPatch g(n, d, std::vector<Vec3>(GBPatch::point_count(n, d)));
  Eigen::MatrixXd a(xs.size(), g.size());
  std::vector<Jet> phi(g.size());
  for (std::size_t r = 0; r < xs.size(); ++r) {
    g.basis(xs[r], phi);
    for (std::size_t c = 0; c < g.size(); ++c) a(r, c) = phi[c].f;
  }
  return a;
}

struct Floor {
  double residual;  // largest |residual| of any degree-d basis function, at any sample
  int rank, columns;
  double conditioning;  // |R_00| / |R_rr| of the pivoted QR (rank r)
};

// Least-squares fit of every degree-d basis function by the degree-(d+1) basis over xs:
// Householder QR with column pivoting (no normal equations).
Floor elevation_floor(int n, int d, const std::vector<Vec2>& xs) {
  const Eigen::MatrixXd a = basis_matrix(n, d, xs), b = basis_matrix(n, d + 1, xs);
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(b);
  qr.setThreshold(1e-12);
  const Eigen::MatrixXd fit = qr.solve(a);
  const int rank = static_cast<int>(qr.rank());
  const auto r = qr.matrixR();
  return {(a - b * fit).cwiseAbs().maxCoeff(), rank, static_cast<int>(b.cols()),
          std::fabs(r(0, 0)) / std::fabs(r(rank - 1, rank - 1))};
}

TEST(GBElevation, ExactElevationExistsOnlyForFourSides) {
  // The table core/patch/gb/elevation.hpp and docs/patch-types.md quote.
  double lo = 1, hi = 0, worst_conditioning = 0, worst_n4 = 0;
  for (int n : {3, 4, 5, 6, 7})
    for (int d = 2; d <= 7; ++d) {
      const auto dom = ConvexPolygonDomain::regular(n);
      // Two independent sample sets: interior points and points on the sides.
      auto xs1 = test::polygon_interior(dom, 900, 1, 1e-3),
           xs2 = test::polygon_interior(dom, 900, 2, 0);
      for (Vec2 x : test::polygon_sides(dom, 12)) xs1.push_back(x);
      const Floor f1 = elevation_floor(n, d, xs1), f2 = elevation_floor(n, d, xs2);
      std::printf(
          "[ lsq floor ] n=%d d=%d->%d: max residual %.2e / %.2e (two sample sets), rank %d/%d, "
          "R conditioning %.1e\n",
          n, d, d + 1, f1.residual, f2.residual, f1.rank, f1.columns, f1.conditioning);
      EXPECT_EQ(f1.rank, f2.rank);
      worst_conditioning = std::max(worst_conditioning, f1.conditioning);
      if (n == 4) {
        // The tensor-product patch: its elevation is exact (rounding of sums of ~40 products of
        // basis values <= 1); only C_0 is redundant for odd d+1.
        EXPECT_LT(f1.residual, 1e-14);
        EXPECT_LT(f2.residual, 1e-14);
        EXPECT_EQ(f1.rank, f1.columns - (d % 2 == 0 ? 1 : 0));
        worst_n4 = std::max({worst_n4, f1.residual, f2.residual});
      } else {
        // Full rank and well conditioned, so the floor is the distance to the degree-(d+1) space
        // and not a numerical artefact; the two sample sets see it alike (the larger set reaches
        // the sides, so it may find up to twice the other's maximum).
        EXPECT_EQ(f1.rank, f1.columns);
        EXPECT_LT(f1.conditioning, 1e4);
        EXPECT_GT(std::min(f1.residual, f2.residual), 2e-4);
        EXPECT_LT(std::max(f1.residual, f2.residual), 1e-2);
        EXPECT_LT(std::max(f1.residual, f2.residual), 2 * std::min(f1.residual, f2.residual));
        lo = std::min({lo, f1.residual, f2.residual});
        hi = std::max({hi, f1.residual, f2.residual});
      }
    }
  std::printf(
      "[ lsq floor ] n=3,5,6,7 d=2..7: residuals %.1e .. %.1e, conditioning <= %.1e; n=4: %.1e\n",
      lo, hi, worst_conditioning, worst_n4);
  ::testing::Test::RecordProperty("lsq_residual_min", std::to_string(lo));
  ::testing::Test::RecordProperty("lsq_residual_max", std::to_string(hi));
}

struct Deviation {
  double p = 0, d1 = 0, d2 = 0;
};
Deviation deviation(const GBPatch& a, const GBPatch& b, const std::vector<Vec2>& xs, double scale) {
  Deviation dev;
  for (Vec2 x : xs) {
    const SurfaceJet s = a.evaluate(x), t = b.evaluate(x);
    dev.p = std::max(dev.p, test::max_abs(s.p - t.p) / scale);
    dev.d1 =
        std::max({dev.d1, test::max_abs(s.su - t.su) / scale, test::max_abs(s.sv - t.sv) / scale});
    dev.d2 = std::max({dev.d2, test::max_abs(s.suu - t.suu) / scale,
                       test::max_abs(s.suv - t.suv) / scale, test::max_abs(s.svv - t.svv) / scale});
  }
  return dev;
}

TEST(GBElevation, FourSidedElevationChangesNoSample) {
  for (int d = 2; d <= 6; ++d) {
    const GBPatch g = test::random_gb(4, d, 20 + d);
    const GBPatch once = gb_elevate(g), twice = gb_elevate(once);
    ASSERT_EQ(once.degree(), d + 1);
    auto xs = test::polygon_interior(g.polygon(), 200, d, 0);
    for (Vec2 x : test::polygon_sides(g.polygon(), 10)) xs.push_back(x);
    xs.push_back({0, 0});
    const double scale = test::bbox_diagonal(g.control_points());
    for (const GBPatch* e : {&once, &twice}) {
      const Deviation dev = deviation(g, *e, xs, scale);
      EXPECT_LT(dev.p, 1e-12) << "d=" << d << "->" << e->degree();
      EXPECT_LT(dev.d1, 1e-12) << "d=" << d << "->" << e->degree();
      EXPECT_LT(dev.d2, 1e-12) << "d=" << d << "->" << e->degree();
      std::printf("[ n=4 elev  ] d=%d->%d max change: value %.2g, first %.2g, second %.2g\n", d,
                  e->degree(), dev.p, dev.d1, dev.d2);
    }
  }
}

TEST(GBElevation, FourSidedNetIsTheTensorProductElevation) {
  // Independent: elevate the tensor-product grid Q[a][b] of the patch (reference README's
  // mapping, side 3 is Q[j][k]) with the textbook formula and compare every stored point.
  double worst_all = 0;
  for (int d = 2; d <= 6; ++d) {
    const GBPatch g = test::random_gb(4, d, 30 + d);
    const auto grid = [&](const GBPatch& p, int a, int b) -> Vec3 {
      const int e = p.degree(), l = p.layers();
      if (b < l) return p.point(3, a, b);
      if (a < l) return p.point(2, e - b, a);
      if (e - a < l) return p.point(0, b, e - a);
      if (e - b < l) return p.point(1, e - a, e - b);
      return p.control_point(0);  // the middle of an even degree
    };
    const GBPatch e = gb_elevate(g);
    const double scale = test::bbox_diagonal(g.control_points());
    double worst = 0;
    for (int a = 0; a <= d + 1; ++a)
      for (int b = 0; b <= d + 1; ++b) {
        Vec3 q(0);
        for (int s = 0; s <= 1; ++s)
          for (int t = 0; t <= 1; ++t) {
            const int aa = a - s, bb = b - t;
            if (aa < 0 || aa > d || bb < 0 || bb > d) continue;
            const double wa = s ? double(a) / (d + 1) : 1 - double(a) / (d + 1);
            const double wb = t ? double(b) / (d + 1) : 1 - double(b) / (d + 1);
            q += wa * wb * grid(g, aa, bb);
          }
        worst = std::max(worst, test::max_abs(grid(e, a, b) - q) / scale);
      }
    // Weights <= 1 on points ~4 across; C_0 of even d+1 is solved for from the centre sample
    // with a central weight >= 0.03 (GBElevation.CentralWeightAtTheCentre), ~30 x rounding.
    EXPECT_LT(worst, 1e-13) << "d=" << d;
    worst_all = std::max(worst_all, worst);
  }
  std::printf("[ n=4 net   ] d=2..6: every point vs the tensor-product elevation %.2g\n",
              worst_all);
}

TEST(GBElevation, EveryRibbonIsItsTensorProductElevation) {
  // Read through every ribbon, shared corner points included: ribbon i of the new net is the
  // textbook elevation of ribbon i's old grid, so the ribbons sharing a corner block agree. Every
  // new row, the innermost one of even d included: it needs the old row d/2, which no ribbon owns;
  // seen from ribbon i it is the tensor-product middle row (as for n = 4, where the grid is the
  // tensor-product net): the middle columns of ribbons i-1 (j < d/2) and i+1 (j > d/2), and C_0.
  double worst = 0;
  int middle_rows = 0;
  for (int n = 3; n <= 9; ++n)
    for (int d = 2; d <= 7; ++d) {
      const GBPatch g = test::random_gb(n, d, 80 + n * d), e = gb_elevate(g);
      const double scale = test::bbox_diagonal(g.control_points());
      const int m = d / 2;
      const auto old_grid = [&](int i, int j, int k) -> Vec3 {
        if (k < g.layers()) return g.point(i, j, k);
        EXPECT_TRUE(d % 2 == 0 && k == m);
        if (j < m) return g.point((i + n - 1) % n, m, j);  // column m of ribbon i-1, from its top
        if (j > m) return g.point((i + 1) % n, m, d - j);
        return g.control_point(0);
      };
      ASSERT_EQ(e.layers(), g.layers() + (d % 2 == 0 ? 1 : 0));
      for (int i = 0; i < n; ++i)
        for (int k = 0; k < e.layers(); ++k)
          for (int j = 0; j <= d + 1; ++j) {
            Vec3 q(0);
            for (int a = 0; a <= 1; ++a)
              for (int b = 0; b <= 1; ++b) {
                if (j - a < 0 || j - a > d || k - b < 0) continue;
                const double wj = a ? double(j) / (d + 1) : 1 - double(j) / (d + 1);
                const double wk = b ? double(k) / (d + 1) : 1 - double(k) / (d + 1);
                if (wj * wk == 0) continue;
                q += wj * wk * old_grid(i, j - a, k - b);
              }
            middle_rows += k == g.layers();
            worst = std::max(worst, test::max_abs(e.point(i, j, k) - q) / scale);
          }
      // Four products of weights <= 1 with coordinates <= ~6, relative to a diagonal ~10: a few
      // ulps.
      ASSERT_LT(worst, 1e-15) << "n=" << n << " d=" << d;
    }
  EXPECT_GT(middle_rows, 0);
  std::printf(
      "[ ribbons   ] n=3..9 d=2..7: every ribbon row vs its own elevation %.2g (%d points of new "
      "innermost rows of even d)\n",
      worst, middle_rows);
}

TEST(GBElevation, KeepsBoundaryAndTangentPlanesForEverySideCount) {
  // Degree 2 is our quadratic variant (no ribbon row 1: its cross derivative comes from C_0 and
  // the neighbouring sides through rational weights); for n != 4 its elevation keeps positions
  // only. The papers' degrees d >= 3 keep first derivatives along the boundary.
  double worst_p = 0, worst_d1 = 0, worst_angle = 0, quadratic_angle = 0;
  for (int n = 3; n <= 12; ++n)
    for (int d = 2; d <= 7; ++d) {
      const GBPatch g = test::random_gb(n, d, 50 + n * d);
      const GBPatch e = gb_elevate(g);
      const double scale = test::bbox_diagonal(g.control_points());
      const bool g1 = d >= 3 || n == 4;
      const auto old_curves = g.boundary_curves(), new_curves = e.boundary_curves();
      for (int i = 0; i < n; ++i)
        for (int t = 0; t <= 10; ++t)
          worst_p = std::max(
              worst_p,
              test::max_abs(old_curves[i].point(t / 10.0) - new_curves[i].point(t / 10.0)) / scale);
      for (Vec2 x : test::polygon_sides(g.polygon(), 16)) {
        const SurfaceJet s = g.evaluate(x), t = e.evaluate(x);
        worst_p = std::max(worst_p, test::max_abs(s.p - t.p) / scale);
        const Vec3 ns = glm::normalize(glm::cross(s.su, s.sv)),
                   nt = glm::normalize(glm::cross(t.su, t.sv));
        const double angle =
            std::atan2(glm::length(glm::cross(ns, nt)), glm::dot(ns, nt)) * 180 / M_PI;
        if (!g1) {
          quadratic_angle = std::max(quadratic_angle, angle);
          continue;
        }
        worst_d1 = std::max(
            {worst_d1, test::max_abs(s.su - t.su) / scale, test::max_abs(s.sv - t.sv) / scale});
        worst_angle = std::max(worst_angle, angle);
      }
      ASSERT_LT(worst_p, 1e-12) << "n=" << n << " d=" << d;
      ASSERT_LT(worst_d1, 1e-12) << "n=" << n << " d=" << d;
      ASSERT_LT(worst_angle, 1e-6) << "n=" << n << " d=" << d;
    }
  std::printf(
      "[ boundary  ] n=3..12 d=2..7: position %.2g; d>=3 or n=4: first derivatives %.2g "
      "(relative), normals %.2g deg; d=2, n!=4: normals differ by up to %.2g deg\n",
      worst_p, worst_d1, worst_angle, quadratic_angle);
}

TEST(GBElevation, CentralWeightAtTheCentre) {
  // C_0's weight at the domain centre in the elevated patch (degree e = d+1 = 3..20): the centre
  // condition needs it; it is 0 only for n = 4 with odd e, where C_0 has no weight at all.
  double smallest_n4 = 1, smallest = 1;
  for (int n = 3; n <= 16; ++n)
    for (int e = 3; e <= GBPatch::kMaxDegree; ++e) {
      const GBPatch g(n, e, std::vector<Vec3>(GBPatch::point_count(n, e)));
      std::vector<Jet> phi(g.size());
      g.basis({0, 0}, phi);
      const double w = std::fabs(phi[0].f);
      if (n == 4 && e % 2 == 1) {
        EXPECT_EQ(w, 0) << "e=" << e;
      } else {
        (n == 4 ? smallest_n4 : smallest) = std::min(n == 4 ? smallest_n4 : smallest, w);
      }
    }
  std::printf("[ centre wt ] |B_0(0,0)|, e=3..20: n=4 even e >= %.3g, n=3..16 except 4 >= %.3g\n",
              smallest_n4, smallest);
  EXPECT_GT(smallest_n4, 0.03);
  EXPECT_GT(smallest, 0.1);
}

TEST(GBElevation, PassesThroughTheOldCentrePoint) {
  // S'(0,0) = S(0,0) for every n and degree: by the choice of C_0 where it has weight there, by
  // the exact tensor-product elevation for n = 4, odd d+1. Solving for C_0 divides rounding of
  // ~d^2 terms by a weight >= 0.03 (CentralWeightAtTheCentre): 1e-12 relative.
  double worst = 0;
  for (int n = 3; n <= 16; ++n)
    for (int d = 2; d < GBPatch::kMaxDegree; ++d) {
      const GBPatch g = test::random_gb(n, d, 300 + 20 * n + d), e = gb_elevate(g);
      const double err = glm::length(e.evaluate({0, 0}).p - g.evaluate({0, 0}).p) /
                         test::bbox_diagonal(g.control_points());
      EXPECT_LT(err, 1e-12) << "n=" << n << " d=" << d;
      worst = std::max(worst, err);
    }
  std::printf("[ centre    ] n=3..16 d=2..19: |S'(0,0) - S(0,0)| <= %.2g (relative)\n", worst);
  ::testing::Test::RecordProperty("centre_error", std::to_string(worst));
}

TEST(GBElevation, InteriorDeviationAndTheCentralPointRule) {
  // For n != 4 the interior moves. How far (relative to the net's diagonal, over interior and
  // side samples), and the same with the two other rules for the new C_0 we considered: keeping
  // the old C_0, and the default-net rule 4 (core/patch/gb/default_net.hpp).
  double lo = 1, hi = 0;
  int ours_best = 0, cases = 0;
  for (int n : {3, 5, 6, 7, 8})
    for (int d = 2; d <= 7; ++d) {
      const GBPatch g = test::random_gb(n, d, 60 + n + d), e = gb_elevate(g);
      auto xs = test::polygon_interior(g.polygon(), 400, n + d, 1e-3);
      for (Vec2 x : test::polygon_sides(g.polygon(), 12)) xs.push_back(x);
      GBPatch keep = e;
      keep.set_control_point(0, g.control_point(0));
      const auto placed = std::make_unique<bool[]>(e.size());  // all but C_0
      for (std::size_t k = 1; k < e.size(); ++k) placed[k] = true;
      const GBPatch def = gb_default_net(e, std::span<const bool>(placed.get(), e.size()));
      const double scale = test::bbox_diagonal(g.control_points());
      double dev[3] = {0, 0, 0};
      for (Vec2 x : xs) {
        const Vec3 s = g.evaluate(x).p;
        int r = 0;
        for (const GBPatch* t : {&e, static_cast<const GBPatch*>(&keep), &def})
          dev[r] = std::max(dev[r], glm::length(t->evaluate(x).p - s) / scale), ++r;
      }
      std::printf(
          "[ interior  ] n=%d d=%d->%d: largest move %.2e (old C_0 kept: %.2e, default-net C_0: "
          "%.2e)\n",
          n, d, d + 1, dev[0], dev[1], dev[2]);
      lo = std::min(lo, dev[0]);
      hi = std::max(hi, dev[0]);
      ++cases;
      ours_best += dev[0] <= dev[1] && dev[0] <= dev[2];
      // core/patch/gb/elevation.hpp, docs/patch-types.md: the interior moves by 0.1 .. 3.3 % of the
      // net's diagonal; the centre rule is never more than 5 % worse than the better of the other
      // two.
      EXPECT_GT(dev[0], 1e-3) << "n=" << n << " d=" << d;
      EXPECT_LT(dev[0], 3.3e-2) << "n=" << n << " d=" << d;
      EXPECT_LT(dev[0], 1.05 * std::min(dev[1], dev[2])) << "n=" << n << " d=" << d;
    }
  std::printf(
      "[ interior  ] n=3,5..8 d=2..7: largest move %.2e .. %.2e; the centre rule is the smallest "
      "of the three in %d of %d cases\n",
      lo, hi, ours_best, cases);
  ::testing::Test::RecordProperty("interior_move_min", std::to_string(lo));
  ::testing::Test::RecordProperty("interior_move_max", std::to_string(hi));
}

TEST(GBElevation, ReferenceModelsAgainstTheAuthorsSamples) {
  // The reference samples are transfinite's evaluations of the original nets: the elevated
  // four-sided models must still reproduce all of them, every model its boundary samples.
  PATCHLAB_REQUIRE_GB_REFERENCE();
  for (const std::string& name : test::gb_reference_models()) {
    const GBPatch patch = read_gbp(test::gb_reference_dir() / (name + ".gbp"));
    const auto samples = test::read_gb_samples(test::gb_reference_dir() / (name + ".samples.txt"));
    const int n = patch.sides();
    const std::size_t boundary_end = n + 1 + 11 * n;  // vertices, centre, side lines
    const double diag = test::bbox_diagonal(patch.control_points());
    const GBPatch once = gb_elevate(patch), twice = gb_elevate(once);
    for (const GBPatch* e : {&once, &twice}) {
      double side = 0, interior = 0;
      for (std::size_t k = 0; k < samples.size(); ++k) {
        const double dev = glm::length(e->evaluate(samples[k].x).p - samples[k].p) / diag;
        const bool on_boundary = k < boundary_end && k != static_cast<std::size_t>(n);  // n: centre
        double& worst = on_boundary ? side : interior;
        worst = std::max(worst, dev);
      }
      EXPECT_LT(side, 1e-12) << name << " degree " << e->degree();
      if (n == 4) {
        EXPECT_LT(interior, 1e-12) << name << " degree " << e->degree();
      }
      std::printf("[ reference ] %-9s d=%d->%d: boundary samples %.2g, interior and centre %.2g\n",
                  name.c_str(), patch.degree(), e->degree(), side, interior);
    }
  }
}

TEST(GBElevation, RejectsDegreesOutsideTheRange) {
  EXPECT_THROW(gb_elevate(test::random_gb(5, 1, 1)), std::invalid_argument);
  EXPECT_THROW(gb_elevate(test::random_gb(5, GBPatch::kMaxDegree, 1)), std::invalid_argument);
}

}  // namespace
}  // namespace pl
