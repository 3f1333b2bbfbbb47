// Face domains from 3D boundaries: the best-fit-plane projection and the angle + arc-length
// heuristic both give back a planar polygon up to a similarity, counter-clockwise.
#include <gtest/gtest.h>

#include <cmath>

#include "core/domain/concave_polygon.hpp"
#include "core/domain/domain_from_boundary.hpp"

namespace pl {
namespace {

const std::vector<Vec2> kL = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};

// Largest deviation after fitting both polygons into [-1, 1]^2 (similarity without rotation).
double shape_difference(std::vector<Vec2> a, std::vector<Vec2> b) {
  fit_unit_box(a);
  fit_unit_box(b);
  double d = 0;
  for (std::size_t i = 0; i < a.size(); ++i) d = std::max(d, glm::length(a[i] - b[i]));
  return d;
}

double signed_area(const std::vector<Vec2>& p) {
  double a = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    a += 0.5 * (p[i].x * p[(i + 1) % p.size()].y - p[i].y * p[(i + 1) % p.size()].x);
  return a;
}

TEST(ConcaveDomainFromBoundary, ProjectionOfATiltedPlanarPolygon) {
  // The L in the plane spanned by orthonormal e1, e2; the loop runs around e1 x e2.
  const Vec3 e1 = glm::normalize(Vec3(1, 0, 1)), e2 = glm::normalize(Vec3(0, 1, 0));
  std::vector<Vec3> pts;
  for (const Vec2& p : kL) pts.push_back(Vec3(5, -2, 1) + p.x * e1 + p.y * e2);
  const std::vector<Vec2> d = project_to_best_fit_plane(pts);
  EXPECT_GT(signed_area(d), 0);  // counter-clockwise, from the loop's own orientation
  // Same shape up to a rotation: compare side lengths and angles via distances between points.
  for (std::size_t i = 0; i < kL.size(); ++i)
    for (std::size_t j = 0; j < kL.size(); ++j)
      EXPECT_NEAR(glm::length(d[i] - d[j]) / glm::length(d[0] - d[1]),
                  glm::length(kL[i] - kL[j]) / glm::length(kL[0] - kL[1]), 1e-12);
  // Reversing the loop reverses the domain's orientation, not the shape.
  std::vector<Vec3> rev(pts.rbegin(), pts.rend());
  EXPECT_GT(signed_area(project_to_best_fit_plane(rev)), 0);
  EXPECT_THROW(project_to_best_fit_plane({Vec3(0), Vec3(1, 1, 1), Vec3(2, 2, 2)}),
               std::invalid_argument);
}

TEST(ConcaveDomainFromBoundary, AngleLengthReproducesAClosedPolygon) {
  // Exact turning angles and lengths of a closed polygon: nothing to normalise or distribute.
  const std::size_t n = kL.size();
  std::vector<double> lengths, turning;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 a = kL[i], b = kL[(i + 1) % n], c = kL[(i + 2) % n];
    lengths.push_back(glm::length(b - a));
    const Vec2 u = b - a, v = c - b;
    turning.push_back(std::atan2(u.x * v.y - u.y * v.x, glm::dot(u, v)));
  }
  const auto d = angle_length_domain(lengths, turning);
  ASSERT_TRUE(d.has_value());
  // Vertex k of the result is the end of edge k, i.e. kL[k + 1]; the first edge runs along +x.
  std::vector<Vec2> expect;
  for (std::size_t k = 0; k < n; ++k) expect.push_back(kL[(k + 1) % n]);
  EXPECT_LT(shape_difference(*d, expect), 1e-12);
}

TEST(ConcaveDomainFromBoundary, AngleLengthClosesPerturbedData) {
  // Lengths and angles off (as from curved 3D edges): the result is a valid simple polygon with
  // the input's convex/reflex pattern; a tiny perturbation moves it only a little.
  std::vector<Vec2> expect;
  for (std::size_t k = 0; k < kL.size(); ++k) expect.push_back(kL[(k + 1) % kL.size()]);
  const std::vector<double> exact_len = {2, 1, 1, 1, 1, 2};
  const std::vector<double> exact_turn = {M_PI / 2, M_PI / 2, -M_PI / 2,
                                          M_PI / 2, M_PI / 2, M_PI / 2};
  for (double eps : {1e-6, 0.05}) {
    std::vector<double> len = exact_len, turn = exact_turn;
    for (std::size_t i = 0; i < len.size(); ++i) {
      len[i] *= 1 + eps * std::sin(3.0 * i + 1);
      turn[i] *= 1 + eps * std::cos(5.0 * i + 2);
    }
    const auto d = angle_length_domain(len, turn);
    ASSERT_TRUE(d.has_value());
    EXPECT_NO_THROW(ConcavePolygonDomain{*d});
    const std::size_t n = d->size();
    for (std::size_t k = 0; k < n; ++k) {
      const Vec2 a = (*d)[k], b = (*d)[(k + 1) % n], c = (*d)[(k + 2) % n];
      const double turn_sign = (b - a).x * (c - b).y - (b - a).y * (c - b).x;
      EXPECT_EQ(turn_sign < 0, k == 1) << eps << " " << k;  // the turn at the end of edge 2
    }
    if (eps < 1e-3) {
      EXPECT_LT(shape_difference(*d, expect), 1e-5);
    }
  }
  EXPECT_FALSE(angle_length_domain({1, 1, 1}, {-1, -1, -1}).has_value());
}

}  // namespace
}  // namespace pl
