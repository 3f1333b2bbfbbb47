// The parts of the export before OpenCASCADE: exact forms by interpolation, the split of
// domains into convex quadrilaterals, side matching, and the pinned fits, each against an
// independent computation.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "cad_test_util.hpp"
#include "core/cad/cad_model.hpp"
#include "core/cad/domain_quads.hpp"
#include "core/cad/exact_surfaces.hpp"
#include "core/cad/side_matching.hpp"
#include "core/cad/spline_fit.hpp"
#include "core/domain/convex_polygon.hpp"
#include "core/patch/gb/gb_patch.hpp"

namespace pl {
namespace {

double cross2(Vec2 a, Vec2 b) {
  return a.x * b.y - a.y * b.x;
}

double polygon_area(const std::vector<Vec2>& P) {
  double a = 0;
  for (std::size_t i = 0; i < P.size(); ++i) a += cross2(P[i], P[(i + 1) % P.size()]);
  return a / 2;
}

TEST(CadPieces, InterpolationRecoversABiquinticPolynomial) {
  // Random Bézier points; the polynomial evaluated by de Casteljau (BezierPatch) is
  // reproduced point for point.
  std::vector<Vec3> pts;
  for (int k = 0; k < 36; ++k) pts.emplace_back(std::sin(k), std::cos(1.3 * k), 0.1 * k);
  const BezierPatch b(5, 5, pts);
  const BezierPatch r = interpolate_polynomial(5, 5, [&](Vec2 x) { return b.evaluate(x).p; });
  for (std::size_t k = 0; k < pts.size(); ++k)
    EXPECT_LT(glm::length(r.control_points()[k] - pts[k]), 1e-12);
}

TEST(CadPieces, ConvexPolygonsSplitCentrallyIntoConvexQuadsCoveringThem) {
  // Up to 12 sides (corners up to 150 degrees) a central split; beyond, a ring of two pieces per
  // side first (halving the corners), then the inner polygon split centrally.
  for (int n : {3, 4, 5, 6, 9, 12, 13, 16}) {
    const std::vector<Vec2> P = domain_polygon(ConvexPolygonDomain::regular(n));
    const std::vector<DomainQuad> q = split_into_quads(P);
    EXPECT_EQ(q.size(), n == 4 ? 1u : std::size_t(n <= 12 ? n : 3 * n));
    double area = 0;
    for (const DomainQuad& d : q) {
      area += polygon_area({d.begin(), d.end()});
      for (int k = 0; k < 4; ++k)
        EXPECT_GT(cross2(d[(k + 1) % 4] - d[k], d[(k + 2) % 4] - d[(k + 1) % 4]), 0);
    }
    EXPECT_NEAR(area, polygon_area(P), 1e-12);
  }
}

TEST(CadPieces, ConcavePolygonIsCutAtItsReflexCorner) {
  // An L: the reflex corner (1, 1) must not be a quad corner of more than 135 degrees.
  const std::vector<Vec2> L{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  const std::vector<DomainQuad> q = split_into_quads(L);
  double area = 0;
  int at_reflex = 0;
  for (const DomainQuad& d : q) {
    area += polygon_area({d.begin(), d.end()});
    for (int k = 0; k < 4; ++k) {
      EXPECT_GT(cross2(d[(k + 1) % 4] - d[k], d[(k + 2) % 4] - d[(k + 1) % 4]), 0);
      if (glm::length(d[k] - Vec2(1, 1)) < 1e-12) ++at_reflex;
    }
  }
  EXPECT_NEAR(area, 3.0, 1e-12);
  EXPECT_EQ(at_reflex, 2);  // the cut gives the 270 degree corner to two quads
}

TEST(CadPieces, SidesMatchForwardsAndBackwards) {
  auto samples = [](Vec3 a, Vec3 b, double bulge) {
    SideSamples s;
    for (std::size_t k = 0; k < kSideParams.size(); ++k) {
      const double t = kSideParams[k];
      s[k] = a + t * (b - a) + Vec3(0, 0, bulge * t * (1 - t));
    }
    return s;
  };
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  const std::vector<SideSamples> sides{samples(a, b, 0.3), samples(b, a, 0.3), samples(a, b, 0.31),
                                       samples(a, c, 0)};
  const std::vector<SideRef> refs{{0, 0}, {1, 2}, {2, 1}, {3, 3}};
  const auto groups = match_sides(sides, refs, 1e-9);
  ASSERT_EQ(groups.size(), 3u);  // {0, 1 reversed}, {2}, {3}
  for (const SideGroup& g : groups)
    if (g.members.size() == 2) {
      EXPECT_EQ(g.members[0].piece + g.members[1].piece, 1);
      EXPECT_FALSE(g.reversed[0]);
      EXPECT_TRUE(g.reversed[1]);
    }
}

// An octant of the unit sphere, (u, v) -> spherical coordinates: a non-polynomial surface with
// closed-form normals (the position itself).
SurfaceFunction octant() {
  return [](std::span<const Vec2> uv, std::span<SurfacePoint> out) {
    const double h = std::numbers::pi / 2;
    for (std::size_t k = 0; k < uv.size(); ++k) {
      const double th = h * (0.15 + 0.7 * uv[k].x), ph = h * (0.1 + 0.8 * uv[k].y);
      const Vec3 p(std::cos(ph) * std::cos(th), std::cos(ph) * std::sin(th), std::sin(ph));
      const Vec3 su = 0.7 * h * Vec3(-std::cos(ph) * std::sin(th), std::cos(ph) * std::cos(th), 0);
      const Vec3 sv =
          0.8 * h * Vec3(-std::sin(ph) * std::cos(th), -std::sin(ph) * std::sin(th), std::cos(ph));
      out[k] = {p, su, sv};
    }
  };
}

TEST(CadPieces, PinnedFitReachesTheToleranceAndKeepsItsSidesExactly) {
  const SurfaceFunction f = octant();
  FitTolerance tol;
  tol.position = 1e-6;
  // Sides: fitted curves (themselves checked), then pinned.
  std::array<CadCurve, 4> sides;
  for (int s = 0; s < 4; ++s) {
    FitTolerance ct = tol;
    ct.position /= 100;
    const CurveFit c = fit_curve(test::side_curve(f, s), 3, ct);
    ASSERT_TRUE(c.converged);
    sides[s] = c.curve;
  }
  const SurfaceFit fit = fit_surface(f, sides, tol);
  ASSERT_TRUE(fit.converged);
  // Independently: distance to the sphere and normal against the radius, on a grid denser
  // than the fit's check grid.
  double worst_r = 0, worst_n = 0;
  for (int a = 0; a <= 200; ++a)
    for (int b = 0; b <= 200; ++b) {
      const CadSurface::Jet1 e = fit.surface.evaluate(a / 200.0, b / 200.0);
      worst_r = std::max(worst_r, std::fabs(glm::length(e.p) - 1));
      const Vec3 n = glm::normalize(glm::cross(e.su, e.sv));
      worst_n = std::max(worst_n, std::acos(std::min(1.0, glm::dot(n, glm::normalize(e.p)))));
    }
  EXPECT_LE(worst_r, 1e-6);
  EXPECT_LE(worst_n * 180 / std::numbers::pi, 0.05);
  // The boundary rows are the pinned curves.
  for (int k = 0; k <= 50; ++k) {
    const double t = k / 50.0;
    EXPECT_LT(glm::length(fit.surface.evaluate(t, 0).p - sides[0].evaluate(t).p), 1e-14);
    EXPECT_LT(glm::length(fit.surface.evaluate(1, t).p - sides[1].evaluate(t).p), 1e-14);
    EXPECT_LT(glm::length(fit.surface.evaluate(t, 1).p - sides[2].evaluate(t).p), 1e-14);
    EXPECT_LT(glm::length(fit.surface.evaluate(0, t).p - sides[3].evaluate(t).p), 1e-14);
  }
}

TEST(CadPieces, NeighboursShareTheirFittedSeamExactly) {
  // A GB pentagon (five pieces around the centre): each seam is one curve for both pieces.
  std::vector<Vec3> pts;
  const int n = 5, d = 3;
  for (std::size_t k = 0; k < GBPatch::point_count(n, d); ++k)
    pts.emplace_back(std::cos(0.7 * k), std::sin(0.7 * k), 0.05 * std::sin(3.1 * k));
  Scene scene;
  scene.patches.push_back({"gb", std::make_shared<GBPatch>(n, d, pts)});
  const CadModel m = build_cad_model(cad_pieces(scene, std::nullopt, "test"), {});
  ASSERT_EQ(m.faces.size(), 5u);
  EXPECT_EQ(m.shared_fitted_curves, 5);
  // Piece i's side 3 (u = 0: corner -> previous midpoint... ) and piece i-1's side 1 lie on the
  // same seam; compare them as point sets along the curve.
  for (int i = 0; i < n; ++i) {
    const CadSurface& a = m.faces[i].surface;
    const CadSurface& b = m.faces[(i + n - 1) % n].surface;
    double worst = 1e300;
    for (int sa : {1, 2}) {
      for (int sb : {1, 2}) {
        for (bool rev : {false, true}) {
          double w = 0;
          for (int k = 0; k <= 20; ++k) {
            const double t = k / 20.0, s = rev ? 1 - t : t;
            const Vec3 pa = sa == 1 ? a.evaluate(1, t).p : a.evaluate(t, 1).p;
            const Vec3 pb = sb == 1 ? b.evaluate(1, s).p : b.evaluate(s, 1).p;
            w = std::max(w, glm::length(pa - pb));
          }
          worst = std::min(worst, w);
        }
      }
    }
    EXPECT_LT(worst, 1e-14) << "piece " << i;
  }
}

}  // namespace
}  // namespace pl
