// Properties of the convex GB patch checked against independent computations: tensor-product
// Bézier patches (n = 4), planes, the boundary ribbons (interpolation, G1), finite differences,
// the basis, and the evaluator's incremental drag.
#include <gtest/gtest.h>

#include "core/eval/patch_evaluator.hpp"
#include "core/patch/bezier_patch.hpp"
#include "gb_domain_samples.hpp"
#include "gb_test_util.hpp"
#include "test_util.hpp"

namespace pl {
namespace {

// The GB net of a tensor-product net Q (README of the reference folder).
GBPatch gb_from_tensor(const BezierPatch& tp, const Vec3& centre) {
  const int d = tp.degree_u();
  std::vector<Vec3> p(GBPatch::point_count(4, d), centre);
  GBPatch shape(4, d, p);
  for (int k = 0; k < shape.layers(); ++k)
    for (int j = 0; j <= d; ++j) {
      p[shape.index(0, j, k)] = tp.at(d - k, j);
      p[shape.index(1, j, k)] = tp.at(d - j, d - k);
      p[shape.index(2, j, k)] = tp.at(k, d - j);
      p[shape.index(3, j, k)] = tp.at(j, k);
    }
  if (d % 2 == 0) p[0] = tp.at(d / 2, d / 2);
  return GBPatch(4, d, std::move(p));
}

BezierPatch random_tensor(int d, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> z(-3, 3);
  std::vector<Vec3> q;
  for (int a = 0; a <= d; ++a)
    for (int b = 0; b <= d; ++b) q.emplace_back(10.0 * a / d, 10.0 * b / d, z(rng));
  return BezierPatch(d, d, std::move(q));
}

// Largest difference of two jets relative to scale, per derivative order.
struct JetError {
  double p = 0, d1 = 0, d2 = 0;
};
JetError jet_error(const SurfaceJet& a, const SurfaceJet& b) {
  using test::max_abs;
  return {max_abs(a.p - b.p), std::max(max_abs(a.su - b.su), max_abs(a.sv - b.sv)),
          std::max({max_abs(a.suu - b.suu), max_abs(a.suv - b.suv), max_abs(a.svv - b.svv)})};
}

TEST(GBPatch, PointCountIndexingAndKinds) {
  EXPECT_EQ(GBPatch::point_count(5, 5), 46u);  // gbp-format.md's example
  for (int n = 3; n <= 8; ++n)
    for (int d = 1; d <= 7; ++d) {
      const int l = (d + 1) / 2;
      ASSERT_EQ(GBPatch::point_count(n, d), 1u + n * l * (d / 2 + 1));
      const GBPatch g = test::random_gb(n, d, 1);
      std::vector<int> seen(g.size(), 0);
      for (int i = 0; i < n; ++i)
        for (int k = 0; k < l; ++k)
          for (int j = 0; j <= d; ++j) {
            const std::size_t s = g.index(i, j, k);
            ASSERT_GE(s, 1u);
            ++seen[s];
            // The sharing rules of the README.
            if (j < l) {
              ASSERT_EQ(s, g.index(i - 1, d - k, j));
            }
            if (d - j < l) {
              ASSERT_EQ(s, g.index(i + 1, k, d - j));
            }
          }
      for (std::size_t s = 1; s < g.size(); ++s) ASSERT_GE(seen[s], 1) << s;
      EXPECT_EQ(g.kind(0), ControlPointKind::Central);
      EXPECT_EQ(g.kind(1), ControlPointKind::Boundary);
      EXPECT_EQ(g.kind(n * d), ControlPointKind::Boundary);
      if (l > 1) {
        EXPECT_EQ(g.kind(n * d + 1), ControlPointKind::Inner);
      }
    }
  EXPECT_THROW(GBPatch(2, 3, {}), std::invalid_argument);
  EXPECT_THROW(GBPatch(5, 0, {}), std::invalid_argument);
  EXPECT_THROW(GBPatch(5, 5, std::vector<Vec3>(45)), std::invalid_argument);
}

TEST(GBPatch, FourSidedEqualsTensorProductBezier) {
  // d >= 3: the papers' claim; d = 2: our quadratic variant (one-half corner weights).
  for (int d = 2; d <= 6; ++d) {
    const BezierPatch tp = random_tensor(d, 10 + d);
    const GBPatch gb = gb_from_tensor(tp, {1.0, -2.0, 7.0});  // C_0 matters only for even d
    const double scale = test::bbox_diagonal(tp.control_points());
    auto xs = test::polygon_interior(gb.polygon(), 200, 3, 0);
    for (int i = 0; i < 4; ++i)
      for (int t = 0; t <= 10; ++t) xs.push_back(gb.polygon().side_point(i, t / 10.0));
    xs.push_back({0, 0});
    JetError worst;
    for (Vec2 x : xs) {
      const SurfaceJet g = gb.evaluate(x);
      SurfaceJet t = tp.evaluate({(x.x + 1) / 2, (x.y + 1) / 2});
      // x_dom = 2u - 1: each derivative order brings a factor 1/2.
      t.su *= 0.5, t.sv *= 0.5, t.suu *= 0.25, t.suv *= 0.25, t.svv *= 0.25;
      const JetError e = jet_error(g, t);
      worst.p = std::max(worst.p, e.p), worst.d1 = std::max(worst.d1, e.d1);
      worst.d2 = std::max(worst.d2, e.d2);
    }
    EXPECT_LT(worst.p / scale, 1e-12) << "d=" << d;
    EXPECT_LT(worst.d1 / scale, 1e-12) << "d=" << d;
    EXPECT_LT(worst.d2 / scale, 1e-12) << "d=" << d;
    std::printf("[ tensor    ] d=%d max error value %.2g, first %.2g, second %.2g (relative)\n", d,
                worst.p / scale, worst.d1 / scale, worst.d2 / scale);
  }
}

TEST(GBPatch, PlanarNetGivesThePlane) {
  for (int n = 3; n <= 9; ++n)
    for (int d = 2; d <= 6; ++d) {
      GBPatch g = test::random_gb(n, d, 2);
      std::vector<Vec3> p = g.control_points();
      for (Vec3& q : p) q.z = 0.3 * q.x - 0.7 * q.y + 2;  // every point on one plane
      const GBPatch flat(n, d, p);
      const Vec3 normal = glm::normalize(Vec3(-0.3, 0.7, 1));
      auto xs = test::polygon_interior(flat.polygon(), 50, n * 10 + d, 1e-3);
      for (int i = 0; i < n; ++i) xs.push_back(flat.polygon().vertex(i));
      for (Vec2 x : xs) {
        const SurfaceJet s = flat.evaluate(x);
        ASSERT_NEAR(s.p.z, 0.3 * s.p.x - 0.7 * s.p.y + 2, 1e-12 * 10) << n << " " << d;
        for (const Vec3& v : {s.su, s.sv, s.suu, s.suv, s.svv})
          ASSERT_NEAR(glm::dot(v, normal), 0, 1e-10) << n << " " << d;
      }
    }
}

TEST(GBPatch, InterpolatesBoundaryCurves) {
  for (int n = 3; n <= 10; ++n)
    for (int d = 1; d <= 7; ++d) {
      const GBPatch g = test::random_gb(n, d, 3);
      const double scale = test::bbox_diagonal(g.control_points());
      const auto curves = g.boundary_curves();
      ASSERT_EQ(curves.size(), static_cast<std::size_t>(n));
      for (int i = 0; i < n; ++i) {
        ASSERT_EQ(curves[i].degree(), d);
        for (int t = 0; t <= 40; ++t) {
          const Vec2 x = g.domain().side_point(i, t / 40.0);
          const double e = glm::length(g.evaluate(x).p - curves[i].point(t / 40.0));
          ASSERT_LT(e / scale, 1e-12) << "n=" << n << " d=" << d << " side " << i << " t=" << t;
        }
      }
    }
}

// The ribbon of side i: R(s, h) = sum_{j, k<l} B_j^d(s) B_k^d(h) P^i_{j,k}; its normal at h = 0.
Vec3 ribbon_normal(const GBPatch& g, int i, double s) {
  const int d = g.degree();
  std::vector<Vec3> row0, cross;
  for (int j = 0; j <= d; ++j) {
    row0.push_back(g.point(i, j, 0));
    cross.push_back(double(d) * (g.point(i, j, 1) - g.point(i, j, 0)));
  }
  const Vec3 along = BezierCurve(row0).evaluate(s).d1;
  const Vec3 inward = BezierCurve(cross).point(s);
  return glm::normalize(glm::cross(along, inward));
}

double angle_deg(Vec3 a, Vec3 b) {
  a = glm::normalize(a), b = glm::normalize(b);
  return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b)) * 180 / M_PI;
}

TEST(GBPatch, TangentToTheRibbonsAlongEverySide) {
  double worst = 0;
  for (int n = 3; n <= 10; ++n)
    for (int d = 3; d <= 7; ++d) {
      const GBPatch g = test::random_gb(n, d, 4);
      for (int i = 0; i < n; ++i)
        for (int t = 0; t <= 40; ++t) {  // includes both corners (vertex limits)
          const double s = t / 40.0;
          const SurfaceJet S = g.evaluate(g.domain().side_point(i, s));
          // The domain runs counter-clockwise and the ribbon's h points inwards, so along the
          // side (s) x inwards (h) has the orientation of Su x Sv.
          const double a = angle_deg(glm::cross(S.su, S.sv), ribbon_normal(g, i, s));
          worst = std::max(worst, a);
          ASSERT_LT(a, 1e-6) << "n=" << n << " d=" << d << " side " << i << " s=" << s;
        }
    }
  std::printf("[ G1        ] largest normal angle to the ribbons: %.3g degrees\n", worst);
}

TEST(GBPatch, DerivativesMatchFiniteDifferences) {
  for (int n = 3; n <= 8; ++n)
    for (int d = 2; d <= 6; ++d) {
      const GBPatch g = test::random_gb(n, d, 5);
      for (Vec2 x : test::polygon_interior(g.polygon(), 20, 7 * n + d, 0.05)) {
        const SurfaceJet s = g.evaluate(x);
        const auto f1 = test::finite_differences(g, x, 1e-5);
        const auto f2 = test::finite_differences(g, x, 1e-4);
        using test::max_abs;
        ASSERT_LT(max_abs(s.su - f1.su), 1e-7) << n << " " << d;
        ASSERT_LT(max_abs(s.sv - f1.sv), 1e-7) << n << " " << d;
        ASSERT_LT(max_abs(s.suu - f2.suu), 1e-4) << n << " " << d;
        ASSERT_LT(max_abs(s.suv - f2.suv), 1e-4) << n << " " << d;
        ASSERT_LT(max_abs(s.svv - f2.svv), 1e-4) << n << " " << d;
      }
    }
}

TEST(GBPatch, VertexLimitsAreTheLimitsFromInside) {
  // At a vertex the value is the corner point; first derivatives are direction-independent
  // limits, so points approaching along a side and along the bisector both converge to them.
  for (int n : {3, 5, 7})
    for (int d : {3, 4, 5}) {
      const GBPatch g = test::random_gb(n, d, 6);
      for (int v = 0; v < n; ++v) {
        const Vec2 c = g.polygon().vertex(v);
        const SurfaceJet at = g.evaluate(c);
        EXPECT_EQ(at.p, g.point(v, d, 0));
        EXPECT_EQ(at.p, g.point(v + 1, 0, 0));
        for (Vec2 dir : {g.polygon().vertex(v - 1) - c, g.polygon().vertex(v + 1) - c,
                         -c + 0.3 * (g.polygon().vertex(v - 1) - c)}) {
          const SurfaceJet near = g.evaluate(c + 1e-6 * dir);
          ASSERT_LT(test::max_abs(near.su - at.su), 1e-3) << n << " " << d << " " << v;
          ASSERT_LT(test::max_abs(near.sv - at.sv), 1e-3) << n << " " << d << " " << v;
        }
        const SurfaceJet ray = g.evaluate(c + 1e-6 * (Vec2(0) - c));  // second derivatives
        ASSERT_LT(test::max_abs(ray.suu - at.suu), 1e-2 * (1 + test::max_abs(at.suu)));
        ASSERT_LT(test::max_abs(ray.svv - at.svv), 1e-2 * (1 + test::max_abs(at.svv)));
      }
    }
}

TEST(GBPatch, BasisAndInfluenceAgreeWithEvaluate) {
  for (int n : {3, 4, 5, 6, 9})
    for (int d : {1, 2, 3, 4, 5, 6}) {
      const GBPatch g = test::random_gb(n, d, 8);
      const double scale = test::bbox_diagonal(g.control_points());
      auto xs = test::polygon_interior(g.polygon(), 20, 9, 0);
      for (int i = 0; i < n; ++i) {
        xs.push_back(g.polygon().vertex(i));
        xs.push_back(g.polygon().side_point(i, 0.3));
      }
      std::vector<Jet> phi(g.size());
      for (Vec2 x : xs) {
        g.basis(x, phi);
        const JetError e = jet_error(combine(g.control_points(), phi), g.evaluate(x));
        ASSERT_LT(e.p / scale, 1e-12) << n << " " << d;
        ASSERT_LT(e.d1 / scale, 1e-11) << n << " " << d;
        ASSERT_LT(e.d2 / scale, 1e-10) << n << " " << d;
        double sum = 0;
        for (const Jet& w : phi) sum += w.f;
        ASSERT_NEAR(sum, 1.0, 1e-13);
      }
      std::vector<Jet> col(xs.size());
      for (std::size_t k = 0; k < g.size(); ++k) {
        g.influence(k, xs, col);
        for (std::size_t p = 0; p < xs.size(); ++p) {
          g.basis(xs[p], phi);
          for (double diff :
               {col[p].f - phi[k].f, col[p].fu - phi[k].fu, col[p].fv - phi[k].fv,
                col[p].fuu - phi[k].fuu, col[p].fuv - phi[k].fuv, col[p].fvv - phi[k].fvv})
            ASSERT_LT(std::fabs(diff), 1e-11) << n << " " << d << " k=" << k;
        }
      }
    }
}

TEST(GBPatch, NoNonFiniteSamples) {
  for (int n = 3; n <= 12; ++n) {
    const auto tess =
        std::make_shared<const Tessellation>(ConvexPolygonDomain::regular(n).tessellate(32));
    for (int d = 2; d <= 7; ++d) {
      PatchEvaluator ev(std::make_shared<GBPatch>(test::random_gb(n, d, 11)), tess);
      for (std::size_t i = 0; i < ev.sample_count(); ++i) {
        const SurfaceJet& s = ev.jets()[i];
        const SurfaceGeometry& g = ev.geometry()[i];
        const double all = s.p.x + s.p.y + s.p.z + s.su.x + s.su.y + s.su.z + s.sv.x + s.sv.y +
                           s.sv.z + s.suu.x + s.suu.y + s.suu.z + s.suv.x + s.suv.y + s.suv.z +
                           s.svv.x + s.svv.y + s.svv.z;
        ASSERT_TRUE(std::isfinite(all)) << "n=" << n << " d=" << d << " sample " << i;
        ASSERT_TRUE(std::isfinite(g.normal.x + g.normal.y + g.normal.z + g.mean + g.gaussian +
                                  g.kmin + g.kmax))
            << "n=" << n << " d=" << d << " sample " << i;
      }
    }
  }
}

TEST(GBPatch, IncrementalDragEqualsFullEvaluation) {
  const auto tess =
      std::make_shared<const Tessellation>(ConvexPolygonDomain::regular(5).tessellate(24));
  auto patch = std::make_shared<GBPatch>(test::random_gb(5, 5, 12));
  PatchEvaluator ev(patch, tess);
  const double scale = test::bbox_diagonal(patch->control_points());
  // Central, boundary, shared corner-block and inner points.
  for (std::size_t k : {std::size_t(0), std::size_t(1), patch->index(1, 1, 1),
                        patch->index(2, 3, 1), patch->index(0, 2, 2), patch->index(3, 4, 0)}) {
    ev.move_control_point(k, patch->control_point(k) + Vec3(0.3, -0.2, 0.5));
    PatchEvaluator fresh(std::shared_ptr<Patch>(patch->clone()), tess);
    for (std::size_t i = 0; i < ev.sample_count(); ++i) {
      const JetError e = jet_error(ev.jets()[i], fresh.jets()[i]);
      ASSERT_LT(e.p / scale, 1e-12) << "k=" << k << " sample " << i;
      ASSERT_LT(e.d1 / scale, 1e-11) << "k=" << k << " sample " << i;
      ASSERT_LT(e.d2 / scale, 1e-10) << "k=" << k << " sample " << i;
    }
  }
}

}  // namespace
}  // namespace pl

namespace pl {
namespace {

// evaluate() and influence() run on tables derived from the control points (the per-group
// ribbon rows of core/patch/gb/ribbon.hpp, the corner-weight masks of influence): after edits of
// every kind of point (central, boundary, shared corner block, inner) they must still equal the
// basis sum.
TEST(GBPatch, FastPathsFollowControlPointEdits) {
  for (int n : {3, 5, 6})
    for (int d : {2, 3, 5, 6}) {
      GBPatch g = test::random_gb(n, d, 21);
      const auto xs = test::polygon_interior(g.polygon(), 40, 22, 0);
      std::mt19937_64 rng(23);
      std::uniform_real_distribution<double> r(-2, 2);
      std::vector<Jet> phi(g.size()), col(xs.size());
      for (std::size_t k : {std::size_t(0), std::size_t(1), g.index(1, 0, 0), g.index(2, 1, 0),
                            g.index(0, d / 2, g.layers() - 1), g.size() - 1}) {
        g.set_control_point(k, g.control_point(k) + Vec3(r(rng), r(rng), r(rng)));
        const double scale = test::bbox_diagonal(g.control_points());
        for (Vec2 x : xs) {
          g.basis(x, phi);
          const JetError e = jet_error(combine(g.control_points(), phi), g.evaluate(x));
          ASSERT_LT(std::max({e.p, e.d1, e.d2}) / scale, 1e-12) << n << " " << d << " k=" << k;
        }
        g.influence(k, xs, col);
        for (std::size_t p = 0; p < xs.size(); ++p) {
          g.basis(xs[p], phi);
          const double m = std::max({1.0, std::fabs(phi[k].fuu), std::fabs(phi[k].fvv)});
          for (double diff :
               {col[p].f - phi[k].f, col[p].fu - phi[k].fu, col[p].fv - phi[k].fv,
                col[p].fuu - phi[k].fuu, col[p].fuv - phi[k].fuv, col[p].fvv - phi[k].fvv})
            ASSERT_LT(std::fabs(diff) / m, 1e-12) << n << " " << d << " k=" << k;
        }
      }
    }
}

}  // namespace
}  // namespace pl
