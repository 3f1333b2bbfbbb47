// Curvature combs (core/curve/curvature_comb, core/patch/side_curve) against independent
// computations: exact circles (NURBS curve and the sides of the NURBS sphere and cylinder sample),
// the circumscribed circle of three nearby curve points, the side curves of Bézier, Gregory and
// GB patches, and degenerate curves that must give zero-length teeth and never NaN.
#include "core/curve/curvature_comb.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <string>

#include "core/curve/curvature.hpp"
#include "core/curve/nurbs_curve.hpp"
#include "core/domain/tessellation_cache.hpp"
#include "core/eval/scene_surfaces.hpp"
#include "core/io/gbp_io.hpp"
#include "core/io/scene_io.hpp"
#include "core/patch/bezier_patch.hpp"
#include "core/patch/side_curve.hpp"
#include "gb_test_util.hpp"
#include "test_util.hpp"

namespace pl {
namespace {

using test::max_abs;

bool finite(const Vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Every tooth of a comb on a circle of radius R about `centre` is (p - centre) / R^2: length
// 1/R (times the scale at the tip), radially outward. Returns the largest deviation.
double circle_deviation(const CurvatureComb& comb, const Vec3& centre, double R) {
  double worst = 0;
  for (std::size_t i = 0; i < comb.points.size(); ++i) {
    EXPECT_NEAR(glm::length(comb.points[i] - centre), R, 1e-14 * (1 + R));
    worst = std::max(worst, max_abs(comb.teeth[i] - (comb.points[i] - centre) / (R * R)));
  }
  return worst;
}

std::filesystem::path asset(const char* name) {
  return std::filesystem::path(PATCHLAB_SOURCE_DIR) / "assets" / name;
}

TEST(CurvatureComb, NurbsCircleHasConstantOutwardTeeth) {
  const Vec3 c(0.3, -1.2, 2.0), x = glm::normalize(Vec3(1, 1, 0)),
                                y = glm::normalize(Vec3(-1, 1, 1));
  const Vec3 y_perp = glm::normalize(y - glm::dot(y, x) * x);
  for (double R : {0.25, 1.0, 7.5}) {
    const NurbsCurve circle = NurbsCurve::circle(c, x, y_perp, R);
    const CurvatureComb comb = curvature_comb(
        [&](double t) {
          return circle.evaluate(circle.t_min() + t * (circle.t_max() - circle.t_min()));
        },
        24);
    const double dev = circle_deviation(comb, c, R);
    EXPECT_LT(dev, 1e-12 / R) << "R = " << R;
    std::printf("circle R = %g: max |tooth - (p - c)/R^2| = %.3g\n", R, dev);
    // The tip at scale s is s / R outside the circle.
    for (std::size_t i = 0; i < comb.points.size(); ++i)
      EXPECT_NEAR(glm::length(comb.tip(i, 0.4) - c), R + 0.4 / R, 1e-12 * (R + 1 / R));
  }
}

TEST(CurvatureComb, SidesOfTheNurbsSampleAreExactCirclesOrPoles) {
  // The sphere (R = 1 about the origin): sides 0 and 2 are meridians, 1 and 3 the poles. The
  // cylinder (R = 0.5 about x = 3, y = 0): sides 0 and 2 are circles at z = -1 and 1, sides 1
  // and 3 straight seams.
  const Scene scene = read_scene(asset("classic/nurbs.json"));
  ASSERT_EQ(scene.patches.size(), 2u);
  const Patch& sphere = *scene.patches[0].patch;
  const Patch& cylinder = *scene.patches[1].patch;
  double worst = 0;
  for (int side : {0, 2}) {
    worst = std::max(worst, circle_deviation(side_comb(sphere, side, 32), Vec3(0), 1.0));
    const double z = side == 0 ? -1.0 : 1.0;
    worst =
        std::max(worst, 2 * circle_deviation(side_comb(cylinder, side, 32), Vec3(3.0, 0, z), 0.5));
  }
  EXPECT_LT(worst, 1e-12);
  std::printf("NURBS sample sides: max |tooth - (p - c)/R^2| * R = %.3g\n", worst);
  for (int side : {1, 3}) {
    for (const CurvatureComb& comb : {side_comb(sphere, side, 32), side_comb(cylinder, side, 32)})
      for (const Vec3& t : comb.teeth) EXPECT_EQ(t, Vec3(0)) << "side " << side;
  }
}

// The circle through C(t - h), C(t), C(t + h): its curvature and centre converge to the
// osculating circle's as h^2 (the three points are symmetric in h), so Richardson's step
// (4 f(h/2) - f(h)) / 3 leaves O(h^4). Only point() is used, not the derivatives.
struct Circle {
  Vec3 centre;
  double kappa;
};
Circle circumcircle(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 u = a - b, v = c - b, n = glm::cross(u, v);
  const Vec3 centre =
      b + glm::cross(glm::dot(u, u) * v - glm::dot(v, v) * u, n) / (2 * glm::dot(n, n));
  return {centre, 1 / glm::length(centre - b)};
}

TEST(CurvatureComb, BezierTeethMatchTheCircleThroughNeighbouringPoints) {
  const BezierCurve c({{0, 0, 0}, {1, 2, 0.5}, {2.5, -1, 1}, {4, 0.5, -0.5}});
  const CurvatureComb comb = curvature_comb(c, 16);
  ASSERT_EQ(comb.points.size(), 65u);  // 16 teeth, envelope refined to 64 segments
  EXPECT_EQ(comb.tooth_stride, 4);
  double worst_kappa = 0, worst_direction = 0, worst_formula = 0;
  for (std::size_t i = 1; i + 1 < comb.points.size(); ++i) {
    const double t = double(i) / 64, h = 1e-3;
    const Circle c1 = circumcircle(c.point(t - h), c.point(t), c.point(t + h));
    const Circle c2 = circumcircle(c.point(t - h / 2), c.point(t), c.point(t + h / 2));
    const double kappa = (4 * c2.kappa - c1.kappa) / 3;
    const Vec3 centre = (4.0 * c2.centre - c1.centre) / 3.0;
    const Vec3 tooth = comb.teeth[i];
    worst_kappa = std::max(worst_kappa, std::fabs(glm::length(tooth) - kappa) / kappa);
    // Away from the centre of curvature.
    const Vec3 outward = glm::normalize(comb.points[i] - centre);
    worst_direction = std::max(worst_direction, max_abs(glm::normalize(tooth) - outward));
    // And the comb's kappa is the one of core/curve/curvature.hpp.
    const double exact = curve_curvature(c.evaluate(t));
    worst_formula = std::max(worst_formula, std::fabs(glm::length(tooth) - exact) / exact);
    EXPECT_EQ(comb.points[i], c.point(t));
  }
  std::printf(
      "Bezier comb vs circumcircle: kappa rel %.3g, direction %.3g; vs curve_curvature %.3g\n",
      worst_kappa, worst_direction, worst_formula);
  EXPECT_LT(worst_kappa, 1e-8);
  EXPECT_LT(worst_direction, 1e-8);
  EXPECT_LT(worst_formula, 1e-13);
}

TEST(CurvatureComb, BezierPatchSidesMatchTheirBoundaryCurves) {
  const std::vector<Vec3> points = test::random_points(16, 7);
  const BezierPatch patch(3, 3, points);
  const std::vector<BezierCurve> sides = patch.boundary_curves();
  double worst = 0;
  for (int s = 0; s < 4; ++s) {
    const CurvatureComb a = side_comb(patch, s, 64), b = curvature_comb(sides[s], 64);
    for (std::size_t i = 0; i < a.points.size(); ++i) {
      const double size = 1 + glm::length(b.teeth[i]);
      worst = std::max(worst, max_abs(a.points[i] - b.points[i]));
      worst = std::max(worst, max_abs(a.teeth[i] - b.teeth[i]) / size);
    }
  }
  std::printf("bicubic sides: max deviation from the boundary Bezier's comb %.3g\n", worst);
  EXPECT_LT(worst, 1e-12);
  // A border without a comb: the same points (same parameters, same evaluation), no teeth.
  for (int s = 0; s < 4; ++s) {
    const std::vector<Vec3> line = side_polyline(patch, s, 64);
    ASSERT_EQ(line.size(), 65u);
    for (std::size_t i = 0; i < line.size(); ++i)
      EXPECT_LT(max_abs(line[i] - sides[s].point(double(i) / 64)), 1e-12) << s << " " << i;
  }
  EXPECT_THROW(side_polyline(patch, 0, 0), std::invalid_argument);
}

TEST(CurvatureComb, ToothCountBelowOneIsRejected) {
  // Not an assert: a release build would divide by zero computing the tooth stride.
  const BezierCurve arc({{0, 0, 0}, {1, 1, 0}, {2, 0, 0}});
  for (int teeth : {0, -1, -64}) {
    EXPECT_THROW(curvature_comb(arc, teeth), std::invalid_argument) << teeth;
    EXPECT_THROW(side_comb(BezierPatch(1, 1, test::random_points(4, 3)), 0, teeth),
                 std::invalid_argument)
        << teeth;
  }
  const CurvatureComb one = curvature_comb(arc, 1);  // the smallest count: 2 teeth, 64 segments
  EXPECT_EQ(one.points.size(), std::size_t(kMinCombEnvelopeSegments) + 1);
  EXPECT_EQ(one.tooth_stride, kMinCombEnvelopeSegments);
  // Samples taken elsewhere (side_comb's batch) must be as many as the tooth count asks for.
  EXPECT_EQ(curvature_comb_intervals(32), 64);
  EXPECT_EQ(curvature_comb_intervals(100), 100);
  EXPECT_THROW(curvature_comb_of_samples(std::vector<CurvePoint>(64), 32), std::invalid_argument);
  EXPECT_THROW(curvature_comb_intervals(0), std::invalid_argument);
}

// Gregory and GB faces of network scenes (convex, concave, closed) interpolate the network's cubic
// edges; at corners their rational weights are 0/0 and evaluate() returns limits. The side comb
// must still be the edge's comb, corners included.
TEST(CurvatureComb, NetworkFaceSidesMatchTheirEdgesCornersIncluded) {
  TessellationCache cache;
  // Per patch type: the largest deviation inside the sides and at their ends (the corners).
  std::map<std::string, std::pair<double, double>> worst;
  for (const char* file : {"default.json", "gb-concave-l.json", "gregory-blob-closed.json"})
    for (FaceScheme scheme : {FaceScheme::Gregory, FaceScheme::GB}) {
      const SceneSurfaces surfaces =
          evaluate_scene(read_scene(asset(file)), 4, scheme, cache, file);
      for (const SceneSurface& s : surfaces.surfaces) {
        const Patch& p = s.evaluator->patch();
        auto& [inside, corner] = worst[p.type()];
        const std::vector<BezierCurve> sides = p.boundary_curves();
        for (int side = 0; side < p.domain().side_count(); ++side) {
          const CurvatureComb a = side_comb(p, side, 32), b = curvature_comb(sides[side], 32);
          for (std::size_t i = 0; i < a.points.size(); ++i) {
            ASSERT_TRUE(finite(a.teeth[i]) && finite(a.points[i]));
            const double d =
                std::max(max_abs(a.points[i] - b.points[i]),
                         max_abs(a.teeth[i] - b.teeth[i]) / (1 + glm::length(b.teeth[i])));
            double& w = i == 0 || i + 1 == a.points.size() ? corner : inside;
            w = std::max(w, d);
          }
        }
      }
    }
  EXPECT_TRUE(worst.count("gregory-quad") && worst.count("gregory-tri") &&
              worst.count("gb-ribbons"));
  for (const auto& [type, w] : worst) {
    std::printf("%s sides: comb vs edge comb %.3g inside, %.3g at corners\n", type.c_str(), w.first,
                w.second);
    EXPECT_LT(w.first, 1e-12) << type;
    EXPECT_LT(w.second, 1e-12) << type;
  }
}

// Plain GB patches (the reference models, 3 to 7 sides): corner weights are 0/0 there too.
TEST(CurvatureComb, GBReferencePatchSidesMatchTheirBoundaryCurves) {
  PATCHLAB_REQUIRE_GB_REFERENCE();
  for (const std::string& name : test::gb_reference_models()) {
    const GBPatch patch = read_gbp(test::gb_reference_dir() / (name + ".gbp"));
    const std::vector<BezierCurve> sides = patch.boundary_curves();
    double inside = 0, corner = 0;
    for (int side = 0; side < patch.domain().side_count(); ++side) {
      const CurvatureComb a = side_comb(patch, side, 32), b = curvature_comb(sides[side], 32);
      for (std::size_t i = 0; i < a.points.size(); ++i) {
        ASSERT_TRUE(finite(a.teeth[i]) && finite(a.points[i]));
        const double d = std::max(max_abs(a.points[i] - b.points[i]),
                                  max_abs(a.teeth[i] - b.teeth[i]) / (1 + glm::length(b.teeth[i])));
        double& w = i == 0 || i + 1 == a.points.size() ? corner : inside;
        w = std::max(w, d);
      }
    }
    std::printf("gb %-9s sides: comb vs boundary Bezier comb %.3g inside, %.3g at corners\n",
                name.c_str(), inside, corner);
    EXPECT_LT(inside, 1e-12) << name;
    EXPECT_LT(corner, 1e-12) << name;
  }
}

TEST(CurvatureComb, StraightAndDegenerateCurvesGiveZeroTeeth) {
  // Collinear, unevenly spaced: C'' is along C' up to rounding.
  const Vec3 d = glm::normalize(Vec3(0.3, -0.7, 0.2));
  const BezierCurve line({1.0 * d, 1.3 * d, 2.9 * d, 3.1 * d});
  for (const Vec3& t : curvature_comb(line, 40).teeth) EXPECT_EQ(t, Vec3(0));
  // C'(0) = 0 (first handle on its vertex): kappa is undefined there, finite elsewhere.
  const BezierCurve cusp({{0, 0, 0}, {0, 0, 0}, {1, 1, 0}, {2, 0, 0}});
  const CurvatureComb c = curvature_comb(cusp, 8);
  EXPECT_EQ(c.teeth.front(), Vec3(0));
  for (const Vec3& t : c.teeth) EXPECT_TRUE(finite(t));
  EXPECT_GT(glm::length(c.teeth[1]), 0);
  // A point (degree 0) and a curve with every control point equal.
  for (const BezierCurve& b :
       {BezierCurve({{1, 2, 3}}), BezierCurve({{1, 2, 3}, {1, 2, 3}, {1, 2, 3}})})
    for (const Vec3& t : curvature_comb(b, 4).teeth) EXPECT_EQ(t, Vec3(0));
  // Speeds below the rounding level of the coordinates and overflowing quotients.
  EXPECT_EQ(curvature_tooth({{1e3, 0, 0}, {1e-15, 0, 0}, {0, 1, 0}}), Vec3(0));
  EXPECT_EQ(curvature_tooth({{0, 0, 0}, {1e-200, 0, 0}, {0, 1e200, 0}}), Vec3(0));
  EXPECT_EQ(curvature_tooth({{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}), Vec3(0));
}

TEST(CurvatureComb, AutomaticScaleUsesThePercentileAndIgnoresStraightCurves) {
  // Circles of radius 1 (kappa 1) and one of radius 1e-3 (kappa 1000): the one small circle
  // is fewer than 10 % of the teeth, so the reference curvature stays 1.
  std::vector<CurvatureComb> combs;
  for (int k = 0; k < 60; ++k) {
    const NurbsCurve circle = NurbsCurve::circle(Vec3(k, 0, 0), {1, 0, 0}, {0, 1, 0}, 1.0);
    combs.push_back(curvature_comb([&](double t) { return circle.evaluate(t); }, 64));
  }
  const NurbsCurve small = NurbsCurve::circle(Vec3(0), {1, 0, 0}, {0, 1, 0}, 1e-3);
  combs.push_back(curvature_comb([&](double t) { return small.evaluate(t); }, 64));
  EXPECT_NEAR(automatic_comb_scale(combs, 10.0, 0.1), 1.0, 1e-12);
  // Straight curves alone: no scale (0), whatever the rounding left in C''.
  const BezierCurve line({{0, 0, 0}, {0.1, 0.1, 0.1}, {0.7, 0.7, 0.7}, {1, 1, 1}});
  const std::vector<CurvatureComb> straight{curvature_comb(line, 8)};
  EXPECT_EQ(automatic_comb_scale(straight, 2.0), 0.0);
  EXPECT_EQ(automatic_comb_scale({}, 2.0), 0.0);
}

}  // namespace
}  // namespace pl
