// Properties of every ribbon-based scheme (core/patch/transfinite), each checked against an
// independent computation: boundary interpolation (the curves evaluated on their own), G1 to the
// ribbons (the normal against the plane of the curve tangent and the cross derivative), the same
// surface after a rotation of the sides, reproduction of a plane, exact derivatives against
// finite differences, the basis against evaluate(), and the curve forms (B-spline, NURBS) against
// the Bézier they equal.
#include <gtest/gtest.h>

#include <cstdio>
#include <random>

#include "core/curve/scene_curve.hpp"
#include "ribbon_test_util.hpp"

namespace pl {
namespace {

using transfinite::RibbonScheme;

std::string label(RibbonScheme s, int n) {
  return std::string(transfinite::ribbon_scheme_name(s)) + " face" + std::to_string(n);
}

// Points strictly inside the domain: random convex combinations of the vertices.
std::vector<Vec2> interior_points(const ConvexPolygonDomain& d, int count, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.05, 1.0);
  std::vector<Vec2> out;
  for (int k = 0; k < count; ++k) {
    Vec2 p(0);
    double sum = 0;
    for (const Vec2& v : d.vertices()) {
      const double w = u(rng);
      p += w * v;
      sum += w;
    }
    out.push_back(p / sum);
  }
  return out;
}

bool finite(const SurfaceJet& s) {
  for (const Vec3& v : {s.p, s.su, s.sv, s.suu, s.suv, s.svv})
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) return false;
  return true;
}

TEST(RibbonSchemes, InterpolateTheBoundaryCurves) {
  for (RibbonScheme s : transfinite::all_ribbon_schemes())
    for (int n = 3; n <= 6; ++n) {
      const auto sides = test::reference_face(n);
      const RibbonPatch p(s, sides);
      const double size = test::points_diagonal(sides);
      double worst = 0;
      for (int i = 0; i < n; ++i) {
        const BezierCurve c(sides[std::size_t(i)].curve.points);  // the side on its own
        for (int k = 0; k <= 40; ++k) {
          const double t = k / 40.0;
          const SurfaceJet S = p.evaluate(p.domain().side_point(i, t));
          ASSERT_TRUE(finite(S)) << label(s, n) << " side " << i << " t " << t;
          worst = std::max(worst, glm::length(S.p - c.point(t)) / size);
        }
      }
      EXPECT_LT(worst, 1e-12) << label(s, n);
    }
}

TEST(RibbonSchemes, AreG1ToTheirRibbons) {
  // Along side i the normal Su x Sv must be normal to P_i'(t) and D_i(t), corners included.
  for (RibbonScheme s : transfinite::all_ribbon_schemes())
    for (int n = 3; n <= 6; ++n) {
      const auto sides = test::reference_face(n);
      const RibbonPatch p(s, sides);
      double worst = 0;
      for (int i = 0; i < n; ++i) {
        const BezierCurve c(sides[std::size_t(i)].curve.points),
            d(sides[std::size_t(i)].cross.points);
        for (int k = 0; k <= 40; ++k) {
          const double t = k / 40.0;
          const SurfaceJet S = p.evaluate(p.domain().side_point(i, t));
          const Vec3 normal = glm::normalize(glm::cross(S.su, S.sv));
          const Vec3 plane = glm::normalize(glm::cross(c.evaluate(t).d1, d.point(t)));
          const double angle = std::asin(std::min(1.0, glm::length(glm::cross(normal, plane))));
          worst = std::max(worst, angle * 180 / M_PI);
        }
      }
      EXPECT_LT(worst, 1e-8) << label(s, n);
      std::printf("[ g1 ] %-24s max angle to the ribbon plane %.3g deg\n", label(s, n).c_str(),
                  worst);
    }
}

TEST(RibbonSchemes, AreTheSameSurfaceAfterARotationOfTheSides) {
  // Side i+1 as side i: on the regular n-gon the surface is the old one at the domain point
  // turned by one vertex. (The side-based scheme's default domain is built from the curves, its
  // open chain closed starting from side 0 as the research library does, so with it the scheme
  // is not exactly symmetric; it is given the regular n-gon here like the others.)
  for (RibbonScheme s : transfinite::all_ribbon_schemes())
    for (int n = 3; n <= 6; ++n) {
      const auto sides = test::reference_face(n);
      std::vector<RibbonSide> turned(sides.begin() + 1, sides.end());
      turned.push_back(sides[0]);
      RibbonPatchOptions regular;
      regular.domain = ConvexPolygonDomain::regular(n).vertices();
      const RibbonPatch a(s, sides, regular), b(s, turned, regular);
      const double size = test::points_diagonal(sides);
      const double angle = 2 * M_PI / n;
      double worst = 0;
      for (Vec2 x : interior_points(b.polygon(), 100, 7)) {
        const Vec2 r(std::cos(angle) * x.x - std::sin(angle) * x.y,
                     std::sin(angle) * x.x + std::cos(angle) * x.y);
        worst = std::max(worst, glm::length(a.evaluate(r).p - b.evaluate(x).p) / size);
      }
      EXPECT_LT(worst, 1e-12) << label(s, n);
    }
}

TEST(RibbonSchemes, ReproduceAPlane) {
  // Ribbons in the plane z = 0.3 x - 0.2 y + 1 (curves on it, cross derivatives along it): every
  // point, first and second derivative must lie in it.
  const auto to_plane = [](Vec3 p, bool vector) {
    return Vec3(p.x, p.y, 0.3 * p.x - 0.2 * p.y + (vector ? 0.0 : 1.0));
  };
  for (RibbonScheme s : transfinite::all_ribbon_schemes())
    for (int n = 3; n <= 6; ++n) {
      auto sides = test::reference_face(n);
      for (RibbonSide& r : sides) {
        for (Vec3& q : r.curve.points) q = to_plane(q, false);
        for (Vec3& q : r.cross.points) q = to_plane(q, true);
      }
      const RibbonPatch p(s, sides);
      const Vec3 normal = glm::normalize(Vec3(0.3, -0.2, -1));
      double worst = 0, worst_vertex = 0;
      std::vector<Vec2> xs = interior_points(p.polygon(), 100, 3);
      for (int i = 0; i < n; ++i)
        for (int k = 1; k < 10; ++k) xs.push_back(p.domain().side_point(i, k / 10.0));
      for (Vec2 x : xs) {
        const SurfaceJet S = p.evaluate(x);
        worst = std::max(worst, std::abs(glm::dot(S.p - Vec3(0, 0, 1), normal)));
        for (const Vec3& d : {S.su, S.sv, S.suu, S.suv, S.svv})
          worst = std::max(worst, std::abs(glm::dot(d, normal)) / (1 + glm::length(d)));
      }
      EXPECT_LT(worst, 1e-12) << label(s, n);
      // At the vertices: position and first derivatives exact; the second derivatives are the
      // scheme's at 1e-4 of the domain from the vertex, where the blends' rounding is magnified
      // by about 1e8 (ribbon_patch.hpp).
      for (const Vec2& v : p.polygon().vertices()) {
        const SurfaceJet S = p.evaluate(v);
        worst = std::max(worst, std::abs(glm::dot(S.p - Vec3(0, 0, 1), normal)));
        for (const Vec3& d : {S.su, S.sv})
          worst = std::max(worst, std::abs(glm::dot(d, normal)) / (1 + glm::length(d)));
        for (const Vec3& d : {S.suu, S.suv, S.svv})
          worst_vertex =
              std::max(worst_vertex, std::abs(glm::dot(d, normal)) / (1 + glm::length(d)));
      }
      EXPECT_LT(worst, 1e-12) << label(s, n);
      EXPECT_LT(worst_vertex, 1e-7) << label(s, n);
    }
}

TEST(RibbonSchemes, DerivativesAgreeWithFiniteDifferences) {
  for (RibbonScheme s : transfinite::all_ribbon_schemes())
    for (int n = 3; n <= 6; ++n) {
      const RibbonPatch p(s, test::reference_face(n));
      const double h = 1e-5;
      double worst1 = 0, worst2 = 0;
      for (Vec2 x : interior_points(p.polygon(), 40, 11)) {
        const SurfaceJet S = p.evaluate(x);
        const SurfaceJet U1 = p.evaluate(x + Vec2(h, 0)), U0 = p.evaluate(x - Vec2(h, 0));
        const SurfaceJet V1 = p.evaluate(x + Vec2(0, h)), V0 = p.evaluate(x - Vec2(0, h));
        const double scale1 = glm::length(S.su) + glm::length(S.sv);
        worst1 = std::max(worst1, glm::length((U1.p - U0.p) / (2 * h) - S.su) / scale1);
        worst1 = std::max(worst1, glm::length((V1.p - V0.p) / (2 * h) - S.sv) / scale1);
        const double scale2 = 1 + glm::length(S.suu) + glm::length(S.suv) + glm::length(S.svv);
        worst2 = std::max(worst2, glm::length((U1.su - U0.su) / (2 * h) - S.suu) / scale2);
        worst2 = std::max(worst2, glm::length((V1.su - V0.su) / (2 * h) - S.suv) / scale2);
        worst2 = std::max(worst2, glm::length((U1.sv - U0.sv) / (2 * h) - S.suv) / scale2);
        worst2 = std::max(worst2, glm::length((V1.sv - V0.sv) / (2 * h) - S.svv) / scale2);
      }
      EXPECT_LT(worst1, 1e-7) << label(s, n);
      EXPECT_LT(worst2, 1e-6) << label(s, n);
    }
}

TEST(RibbonSchemes, BasisAndInfluenceAgreeWithEvaluate) {
  for (RibbonScheme s : transfinite::all_ribbon_schemes())
    for (int n : {3, 5}) {
      RibbonPatchOptions o;
      if (transfinite::has_central_point(s)) o.midpoint = Vec3(0.5, -0.2, 3.0);
      const RibbonPatch p(s, test::reference_face(n), o);
      const double size = test::points_diagonal(p.sides());
      std::vector<Vec2> xs = interior_points(p.polygon(), 10, 5);
      xs.push_back(p.domain().side_point(1, 0.3));
      std::vector<Jet> phi(p.size());
      for (Vec2 x : xs) {
        p.basis(x, phi);
        const SurfaceJet a = combine(p.control_points(), phi), b = p.evaluate(x);
        EXPECT_LT(glm::length(a.p - b.p) / size, 1e-12) << label(s, n);
        EXPECT_LT(glm::length(a.su - b.su) / (1 + glm::length(b.su)), 1e-12) << label(s, n);
        EXPECT_LT(glm::length(a.svv - b.svv) / (1 + glm::length(b.svv)), 1e-9) << label(s, n);
      }
      std::size_t k = p.size() / 2;
      std::vector<Jet> col(xs.size());
      p.influence(k, xs, col);
      for (std::size_t i = 0; i < xs.size(); ++i) {
        p.basis(xs[i], phi);
        EXPECT_NEAR(col[i].f, phi[k].f, 1e-14) << label(s, n);
        EXPECT_NEAR(col[i].fu, phi[k].fu, 1e-12) << label(s, n);
      }
      // A moved point changes the surface by its basis function times the move. (The side-based
      // scheme's default domain follows the curves, so a curve point moves the domain too:
      // RibbonSideBasedDomain tests that; here its move is a cross-derivative vector.)
      if (s == RibbonScheme::SideBased)
        while (p.kind(k) != ControlPointKind::Inner) --k;
      RibbonPatch q = p;
      const Vec3 move(0.1, -0.2, 0.3);
      q.set_control_point(k, p.control_point(k) + move);
      for (Vec2 x : xs) {
        p.basis(x, phi);
        const Vec3 expected = p.evaluate(x).p + phi[k].f * move;
        EXPECT_LT(glm::length(q.evaluate(x).p - expected) / size, 1e-12) << label(s, n);
      }
    }
}

TEST(RibbonSchemes, MidpointSchemesPassThroughTheirMidpoint) {
  // Not on the square: there the deficient corner blends sum to exactly 1 at the centre, so the
  // central point has no say at that one point (the library then takes C = M).
  for (RibbonScheme s : {RibbonScheme::Midpoint, RibbonScheme::MidpointCoons})
    for (int n : {3, 5, 6}) {
      RibbonPatchOptions o;
      o.midpoint = Vec3(0.4, -0.3, 4.0);
      const RibbonPatch p(s, test::reference_face(n), o);
      EXPECT_LT(glm::length(p.evaluate(Vec2(0)).p - *o.midpoint), 1e-12) << label(s, n);
      // Fullness f: the midpoint c + f (m - c), c the corners' average, m the default midpoint.
      const RibbonPatch plain(s, test::reference_face(n));
      RibbonPatchOptions flat, full;
      flat.fullness = 0;
      full.fullness = 2;
      const RibbonPatch a(s, test::reference_face(n), flat), b(s, test::reference_face(n), full);
      Vec3 c(0);
      for (const RibbonSide& side : plain.sides()) c += side.curve.points.back();
      c /= double(n);
      const Vec3 m = plain.evaluate(Vec2(0)).p;
      EXPECT_LT(glm::length(a.evaluate(Vec2(0)).p - c), 1e-12) << label(s, n);
      EXPECT_LT(glm::length(b.evaluate(Vec2(0)).p - (c + 2.0 * (m - c))), 1e-12) << label(s, n);
    }
}

TEST(RibbonSchemes, SplineAndRationalFormsOfTheSameCurvesGiveTheSameSurface) {
  // Each curve with a knot inserted (a B-spline of two spans) and each cross derivative as a
  // rational Bézier with equal weights (a NURBS): the same curves, so the same surface.
  for (RibbonScheme s : transfinite::all_ribbon_schemes())
    for (int n : {4, 6}) {
      const auto sides = test::reference_face(n);
      std::vector<RibbonSide> other = sides;
      for (RibbonSide& r : other) {
        r.curve = curve_knot_inserted(r.curve, 0.37);
        SceneCurve c;
        c.type = CurveType::Nurbs;
        c.degree = int(r.cross.points.size()) - 1;
        c.points = r.cross.points;
        c.weights.assign(c.points.size(), 2.5);
        for (int k = 0; k <= c.degree; ++k) c.knots.push_back(0);
        for (int k = 0; k <= c.degree; ++k) c.knots.push_back(1);
        r.cross = c;
      }
      ASSERT_EQ(other[0].curve.type, CurveType::BSpline);
      const RibbonPatch a(s, sides), b(s, other);
      const double size = test::points_diagonal(sides);
      for (Vec2 x : interior_points(a.polygon(), 30, 2))
        EXPECT_LT(glm::length(a.evaluate(x).p - b.evaluate(x).p) / size, 1e-12) << label(s, n);
    }
}

TEST(RibbonSchemes, CornerBasedIsGeneralizedCoonsAndMidpointIsMidpointCoonsOnTheSquare) {
  // An identity of the parameterizations on the square (the reference samples show it too).
  const auto sides = test::reference_face(4);
  const double size = test::points_diagonal(sides);
  const RibbonPatch cb(RibbonScheme::CornerBased, sides), gc(RibbonScheme::GeneralizedCoons, sides);
  const RibbonPatch mp(RibbonScheme::Midpoint, sides), mc(RibbonScheme::MidpointCoons, sides);
  for (Vec2 x : interior_points(cb.polygon(), 50, 9)) {
    EXPECT_LT(glm::length(cb.evaluate(x).p - gc.evaluate(x).p) / size, 1e-13);
    EXPECT_LT(glm::length(mp.evaluate(x).p - mc.evaluate(x).p) / size, 1e-13);
  }
}

TEST(RibbonSchemes, IncompatibleCornersAreRefusedNamingTheCorner) {
  auto sides = test::reference_face(5);
  auto moved = sides;
  moved[2].curve.points.back() += Vec3(0, 0, 0.01);  // corner 2 no longer meets side 3
  try {
    RibbonPatch(RibbonScheme::CornerBased, moved);
    FAIL() << "accepted a gap";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("corner 2 "), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("do not meet"), std::string::npos) << e.what();
  }
  auto turned = sides;
  turned[4].cross.points.front() += Vec3(0, 0, 0.5);  // D_4(0) no longer -P_3'(1): corner 3
  try {
    RibbonPatch(RibbonScheme::SideBased, turned);
    FAIL() << "accepted a mismatched cross derivative";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("corner 3 "), std::string::npos) << e.what();
  }
  EXPECT_THROW(RibbonPatch(RibbonScheme::Midpoint,
                           std::vector<RibbonSide>(sides.begin(), sides.begin() + 2)),
               std::invalid_argument);
}

TEST(RibbonSchemes, AreFiniteOnAFineTessellation) {
  for (RibbonScheme s : transfinite::all_ribbon_schemes())
    for (int n = 3; n <= 6; ++n) {
      const RibbonPatch p(s, test::reference_face(n));
      for (Vec2 x : p.domain().tessellate(24).points)
        ASSERT_TRUE(finite(p.evaluate(x))) << label(s, n) << " at " << x.x << ", " << x.y;
    }
}

}  // namespace
}  // namespace pl
