// Degree elevation of the convex GB patch (core/patch/gb_elevation.hpp): whether an exact
// elevation exists (least squares over the basis functions), exactness for n = 4 against an
// independent tensor-product elevation, and what is kept for every n (boundary, tangent planes).
#include "core/patch/gb_elevation.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>

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
  for (int n : {3, 4, 5, 6})
    for (int d : {3, 4}) {
      const auto dom = ConvexPolygonDomain::regular(n);
      // Two independent sample sets: interior points and points on the sides.
      auto xs1 = test::polygon_interior(dom, 900, 1, 1e-3),
           xs2 = test::polygon_interior(dom, 1400, 2, 0);
      for (Vec2 x : test::polygon_sides(dom, 12)) xs1.push_back(x);
      const Floor f1 = elevation_floor(n, d, xs1), f2 = elevation_floor(n, d, xs2);
      std::printf(
          "[ lsq floor ] n=%d d=%d->%d: max residual %.2e / %.2e (two sample sets), rank %d/%d, "
          "R conditioning %.1e\n",
          n, d, d + 1, f1.residual, f2.residual, f1.rank, f1.columns, f1.conditioning);
      EXPECT_EQ(f1.rank, f2.rank);
      if (n == 4) {
        // The tensor-product patch: its elevation is exact; only C_0 is redundant for odd d+1.
        EXPECT_LT(f1.residual, 1e-12);
        EXPECT_LT(f2.residual, 1e-12);
        EXPECT_EQ(f1.rank, f1.columns - (d % 2 == 0 ? 1 : 0));
      } else {
        // Full rank and well conditioned, so the floor is the distance to the degree-(d+1) space
        // and not a numerical artefact: nine orders of magnitude above rounding.
        EXPECT_EQ(f1.rank, f1.columns);
        EXPECT_LT(f1.conditioning, 1e6);
        EXPECT_GT(f1.residual, 1e-5);
        EXPECT_GT(f2.residual, 1e-5);
      }
    }
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
    EXPECT_LT(worst, 1e-14 * 10) << "d=" << d;
  }
}

TEST(GBElevation, EveryRibbonIsItsTensorProductElevation) {
  // Read through every ribbon, shared corner points included: ribbon i of the new net is the
  // textbook elevation of ribbon i of the old one, so the ribbons sharing a corner block agree.
  // Rows k < l only: they need old rows below l, which every ribbon owns (for even d the
  // innermost new row also needs the tensor-product middle row, checked by the n = 4 tests).
  double worst = 0;
  for (int n = 3; n <= 9; ++n)
    for (int d = 2; d <= 7; ++d) {
      const GBPatch g = test::random_gb(n, d, 80 + n * d), e = gb_elevate(g);
      const double scale = test::bbox_diagonal(g.control_points());
      for (int i = 0; i < n; ++i)
        for (int k = 0; k < g.layers() && k < e.layers(); ++k)
          for (int j = 0; j <= d + 1; ++j) {
            Vec3 q(0);
            for (int a = 0; a <= 1; ++a)
              for (int b = 0; b <= 1; ++b) {
                if (j - a < 0 || j - a > d || k - b < 0) continue;
                const double wj = a ? double(j) / (d + 1) : 1 - double(j) / (d + 1);
                const double wk = b ? double(k) / (d + 1) : 1 - double(k) / (d + 1);
                q += wj * wk * g.point(i, j - a, k - b);
              }
            worst = std::max(worst, test::max_abs(e.point(i, j, k) - q) / scale);
          }
      ASSERT_LT(worst, 1e-14 * 10) << "n=" << n << " d=" << d;
    }
  std::printf("[ ribbons   ] n=3..9 d=2..7: every ribbon row k < l vs its own elevation %.2g\n",
              worst);
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

TEST(GBElevation, InteriorDeviationAgainstTheBestPossibleNet) {
  // For n != 4 the interior moves. Measured against the least-squares best degree-(d+1) net for
  // the same surface (no elevation can be closer in the RMS sense over these samples).
  for (int n : {3, 5, 6})
    for (int d : {3, 4}) {
      const GBPatch g = test::random_gb(n, d, 60 + n + d);
      const GBPatch e = gb_elevate(g);
      auto xs = test::polygon_interior(g.polygon(), 1200, n + d, 1e-3);
      for (Vec2 x : test::polygon_sides(g.polygon(), 12)) xs.push_back(x);
      const Eigen::MatrixXd b = basis_matrix(n, d + 1, xs);
      Eigen::MatrixXd target(xs.size(), 3);
      double ours_rms = 0, ours_max = 0;
      for (std::size_t r = 0; r < xs.size(); ++r) {
        const Vec3 s = g.evaluate(xs[r]).p, t = e.evaluate(xs[r]).p;
        target.row(r) << s.x, s.y, s.z;
        ours_rms += glm::dot(s - t, s - t);
        ours_max = std::max(ours_max, glm::length(s - t));
      }
      const Eigen::MatrixXd best = b.colPivHouseholderQr().solve(target);
      const Eigen::MatrixXd res = target - b * best;
      double best_rms = 0, best_max = 0;
      for (Eigen::Index r = 0; r < res.rows(); ++r) {
        best_rms += res.row(r).squaredNorm();
        best_max = std::max(best_max, res.row(r).norm());
      }
      const double count = double(xs.size()), scale = test::bbox_diagonal(g.control_points());
      ours_rms = std::sqrt(ours_rms / count), best_rms = std::sqrt(best_rms / count);
      std::printf(
          "[ interior  ] n=%d d=%d->%d: elevation max %.2e rms %.2e; best possible net max %.2e "
          "rms %.2e (relative to the net's diagonal)\n",
          n, d, d + 1, ours_max / scale, ours_rms / scale, best_max / scale, best_rms / scale);
      EXPECT_LE(best_rms, ours_rms * (1 + 1e-9));  // the solve is the optimum
      EXPECT_GT(best_max / scale, 1e-6);           // and even it cannot be exact
    }
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
