// Edgewise elevation and layer addition of one ribbon of a GB patch with independent ribbons
// (core/patch/gb/ribbon_elevation.hpp): the boundary curves, the surface along every side and its
// first derivatives there are kept (against the original patch); the interior change is measured.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "core/io/patch_codec.hpp"
#include "core/patch/gb/ribbon_elevation.hpp"
#include "gb_test_util.hpp"
#include "test_util.hpp"

namespace pl {
namespace {

std::vector<Vec2> polygon(const std::string& name) {
  if (name == "L") return {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  if (name == "notch") return {{0, 0}, {2, 0}, {2, 2}, {1, 0.6}, {0, 2}};
  std::vector<Vec2> v;  // "pentagon"
  for (int i = 0; i < 5; ++i) v.emplace_back(std::cos(1.2566 * i), std::sin(1.2566 * i));
  return v;
}

// Rows pushed inwards from each side over a wavy height field, with random interior heights;
// side i has degree 3 + i % 3 and 2 + i % 2 layers.
GBRibbonPatch wavy_patch(const std::vector<Vec2>& poly, unsigned seed) {
  const ConcavePolygonDomain dom(poly);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> bump(-0.15, 0.15);
  const auto height = [](Vec2 x) { return 0.4 * std::cos(1.1 * x.x - 0.4) * std::sin(0.9 * x.y); };
  std::vector<std::vector<std::vector<Vec3>>> ribbons(dom.side_count());
  for (int i = 0; i < dom.side_count(); ++i) {
    const int d = 3 + i % 3, l = 2 + i % 2;
    const Vec2 e = glm::normalize(dom.vertex(i) - dom.vertex(i - 1));
    for (int k = 0; k < l; ++k) {
      ribbons[i].emplace_back();
      for (int j = 0; j <= d; ++j) {
        const Vec2 x = dom.side_point(i, double(j) / d) + 0.12 * k * Vec2(-e.y, e.x);
        ribbons[i].back().emplace_back(x.x, x.y, height(x) + (k > 0 ? bump(rng) : 0.0));
      }
    }
  }
  return GBRibbonPatch(dom, ribbons);
}

struct Change {
  double boundary = 0, side = 0, d1 = 0, normal_deg = 0, interior = 0;
};

Change compare(const GBRibbonPatch& a, const GBRibbonPatch& b) {
  Change c;
  const double scale = test::bbox_diagonal(a.control_points());
  const auto ca = a.boundary_curves(), cb = b.boundary_curves();
  for (int i = 0; i < a.sides(); ++i)
    for (int t = 0; t <= 12; ++t)
      c.boundary = std::max(c.boundary,
                            test::max_abs(ca[i].point(t / 12.0) - cb[i].point(t / 12.0)) / scale);
  const Tessellation tess = a.domain().tessellate(10);
  std::vector<char> on_side(tess.points.size(), 0);
  for (const auto& s : tess.sides)
    for (uint32_t k : s) on_side[k] = 1;
  for (std::size_t k = 0; k < tess.points.size(); ++k) {
    const SurfaceJet s = a.evaluate(tess.points[k]), t = b.evaluate(tess.points[k]);
    const double moved = test::max_abs(s.p - t.p) / scale;
    if (!on_side[k]) {
      c.interior = std::max(c.interior, moved);
      continue;
    }
    c.side = std::max(c.side, moved);
    // Su, Sv themselves (relative to the net's diagonal; the domains are about 2 across).
    c.d1 = std::max({c.d1, test::max_abs(s.su - t.su) / scale, test::max_abs(s.sv - t.sv) / scale});
    const Vec3 ns = glm::cross(s.su, s.sv), nt = glm::cross(t.su, t.sv);
    c.normal_deg = std::max(
        c.normal_deg, std::atan2(glm::length(glm::cross(ns, nt)), glm::dot(ns, nt)) * 180 / M_PI);
  }
  return c;
}

TEST(GBRibbonElevation, KeepsTheBoundaryAndItsFirstDerivatives) {
  for (const char* name : {"pentagon", "L", "notch"}) {
    const GBRibbonPatch g = wavy_patch(polygon(name), 3);
    Change worst_e, worst_l;
    for (int side = 0; side < g.sides(); ++side) {
      const GBRibbonPatch e = gb_ribbon_elevate(g, side), l = gb_ribbon_add_layer(g, side);
      ASSERT_EQ(e.degree(side), g.degree(side) + 1);
      ASSERT_EQ(l.layers(side), g.layers(side) + 1);
      for (int i = 0; i < g.sides(); ++i) {
        if (i != side) {
          ASSERT_EQ(e.ribbons()[i], g.ribbons()[i]);
        }
      }
      for (const auto& [patch, worst] : {std::pair{&e, &worst_e}, std::pair{&l, &worst_l}}) {
        const Change c = compare(g, *patch);
        EXPECT_LT(c.boundary, 1e-12) << name << " side " << side;
        EXPECT_LT(c.side, 1e-12) << name << " side " << side;
        EXPECT_LT(c.d1, 1e-12) << name << " side " << side;
        EXPECT_LT(c.normal_deg, 1e-6) << name << " side " << side;
        worst->boundary = std::max(worst->boundary, c.boundary);
        worst->side = std::max(worst->side, c.side);
        worst->d1 = std::max(worst->d1, c.d1);
        worst->normal_deg = std::max(worst->normal_deg, c.normal_deg);
        worst->interior = std::max(worst->interior, c.interior);
      }
    }
    for (const auto& [what, c] : {std::pair{"edgewise", worst_e}, std::pair{"layer   ", worst_l}})
      std::printf(
          "[ ribbons   ] %-8s %s: boundary %.2g, sides %.2g, Su/Sv there %.2g (relative), "
          "normals %.2g deg; interior moves by up to %.2g\n",
          name, what, c.boundary, c.side, c.d1, c.normal_deg, c.interior);
  }
}

TEST(GBRibbonElevation, AddedLayerContinuesARibbonLinearInH) {
  // Rows C_k = C_0 + k D represent C_0 + m h D: the new rows must be C_0 + k m/(m+2) D.
  const GBRibbonPatch g = wavy_patch(polygon("pentagon"), 4);
  auto ribbons = g.ribbons();
  const int side = 0, l = g.layers(side), m = 2 * l - 1;
  for (int k = 1; k < l; ++k)
    for (std::size_t j = 0; j < ribbons[side][0].size(); ++j)
      ribbons[side][k][j] = ribbons[side][0][j] + double(k) * Vec3(0.05, -0.1, 0.2);
  const GBRibbonPatch linear(g.polygon(), ribbons);
  const auto up = gb_ribbon_add_layer(linear, side).ribbons()[side];
  ASSERT_EQ(static_cast<int>(up.size()), l + 1);
  for (int k = 0; k <= l; ++k)
    for (std::size_t j = 0; j < up[k].size(); ++j)
      EXPECT_LT(test::max_abs(up[k][j] - (ribbons[side][0][j] +
                                          double(k) * m / (m + 2) * Vec3(0.05, -0.1, 0.2))),
                // Three products of weights <= 1 with coordinates <= ~2: a few ulps of 2.
                2e-15);
}

TEST(GBRibbonElevation, RejectsAMissingSide) {
  const GBRibbonPatch g = wavy_patch(polygon("L"), 5);
  EXPECT_THROW(gb_ribbon_elevate(g, g.sides()), std::invalid_argument);
  EXPECT_THROW(gb_ribbon_add_layer(g, -1), std::invalid_argument);
}

TEST(GBRibbonElevation, StopsAtTheFormatsLimits) {
  // Up to the limits every step works and the result is readable by the gb-ribbons codec;
  // one more step throws instead of giving a patch that saves but does not read back.
  GBRibbonPatch g = wavy_patch(polygon("pentagon"), 6);
  while (g.degree(0) < GBRibbonPatch::kMaxDegree) g = gb_ribbon_elevate(g, 0);
  while (g.layers(1) < GBRibbonPatch::kMaxLayers) g = gb_ribbon_add_layer(g, 1);
  EXPECT_EQ(g.degree(0), 30);
  EXPECT_EQ(g.layers(1), 15);
  EXPECT_THROW(gb_ribbon_elevate(g, 0), std::invalid_argument);
  EXPECT_THROW(gb_ribbon_add_layer(g, 1), std::invalid_argument);
  // The other sides are not at their limits.
  EXPECT_EQ(gb_ribbon_elevate(g, 1).degree(1), g.degree(1) + 1);
  EXPECT_EQ(gb_ribbon_add_layer(g, 0).layers(0), g.layers(0) + 1);
  // Round trip through the codec at the limits.
  nlohmann::json j;
  kGBRibbonPatchCodec.write(g, j);
  const auto back = kGBRibbonPatchCodec.read(JsonNode(j, "mem.json"));
  EXPECT_EQ(back->control_points(), g.control_points());
}

}  // namespace
}  // namespace pl
