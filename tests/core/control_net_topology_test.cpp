// Control-net connectivity per patch family: segment counts worked out by hand, every segment
// between positions, every position on the net, and derivative arrows whose tips are the Bézier
// handles of the patch's own boundary curves.
#include "core/patch/control_net_topology.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <set>

#include "core/domain/tessellation_cache.hpp"
#include "core/eval/scene_surfaces.hpp"
#include "core/io/scene_io.hpp"
#include "core/patch/bezier_patch.hpp"
#include "core/patch/coons_network_patch.hpp"
#include "core/patch/gb/gb_patch.hpp"
#include "core/patch/gb/gb_ribbon_patch.hpp"
#include "core/patch/gregory_quad.hpp"
#include "core/patch/gregory_tri.hpp"
#include "core/patch/hermite_patch.hpp"
#include "test_util.hpp"

namespace pl {
namespace {

const std::filesystem::path kAssets = std::filesystem::path(PATCHLAB_SOURCE_DIR) / "assets";

std::shared_ptr<Patch> asset_patch(const std::string& file) {
  return read_scene(kAssets / file).patches.at(0).patch;
}

// Segments are normalised and unique, join positions only, and every position is on the net.
void expect_well_formed(const Patch& p, const ControlNetTopology& t, const std::string& what) {
  ASSERT_EQ(t.is_vector.size(), p.size()) << what;
  std::set<std::array<uint32_t, 2>> seen;
  std::vector<int> degree(p.size(), 0);
  for (const auto& s : t.segments) {
    EXPECT_LT(s[0], s[1]) << what;
    ASSERT_LT(s[1], p.size()) << what;
    EXPECT_TRUE(seen.insert(s).second) << what << ": segment twice";
    EXPECT_FALSE(t.is_vector[s[0]] || t.is_vector[s[1]]) << what << ": a vector on a net line";
    ++degree[s[0]], ++degree[s[1]];
  }
  for (std::size_t k = 0; k < p.size(); ++k)
    if (!t.is_vector[k]) {
      EXPECT_GT(degree[k], 0) << what << ": point " << k << " is loose";
    }
}

TEST(ControlNetTopology, GridsHaveRowsAndColumns) {
  const BezierPatch b(3, 2, test::random_points(12, 1));
  const ControlNetTopology t = control_net_topology(b);
  expect_well_formed(b, t, "bezier");
  EXPECT_EQ(t.segments.size(), 3u * 3 + 4 * 2);
  for (const auto& s : t.segments) {  // neighbours in the grid: one step in i or in j
    const int di = std::abs(int(s[0] / 3) - int(s[1] / 3)),
              dj = std::abs(int(s[0] % 3) - int(s[1] % 3));
    EXPECT_EQ(di + dj, 1);
  }
  for (const char* file :
       {"classic/bspline.json", "classic/nurbs.json", "classic/interpolating.json",
        "classic/pair-join.json", "classic/gap-fill.json"}) {
    const auto p = asset_patch(file);
    const ControlNetTopology n = control_net_topology(*p);
    expect_well_formed(*p, n, file);
    EXPECT_TRUE(n.arrows.empty()) << file;
  }
}

TEST(ControlNetTopology, CatmullClarkCageIsTheBaseMeshEdges) {
  const auto p = asset_patch("classic/catmull-clark.json");
  const ControlNetTopology t = control_net_topology(*p);
  expect_well_formed(*p, t, "catmull-clark");
  // A closed box of 24 quads and 26 vertices: Euler V - E + F = 2.
  EXPECT_EQ(t.segments.size(), 26u + 24 - 2);
  const auto ngon = asset_patch("classic/catmull-clark-ngon.json");
  expect_well_formed(*ngon, control_net_topology(*ngon), "catmull-clark-ngon");
}

TEST(ControlNetTopology, GregoryNetsHaveRibbonsAndTwinPairs) {
  const GregoryQuadPatch quad(test::random_points(20, 2));
  const ControlNetTopology q = control_net_topology(quad);
  expect_well_formed(quad, q, "gregory-quad");
  // Per side: 3 boundary segments, the inner row, 2 spokes, the corner's twin pair.
  EXPECT_EQ(q.segments.size(), 4u * 7);
  // The twins splitting P11 (12 on side 0, 19 on side 3) are joined.
  EXPECT_TRUE(std::count(q.segments.begin(), q.segments.end(), std::array<uint32_t, 2>{12, 19}));
  const GregoryTriPatch tri(test::random_points(18, 3));
  const ControlNetTopology t = control_net_topology(tri);
  expect_well_formed(tri, t, "gregory-tri");
  // Per side: 4 boundary segments, the inner row, 4 zigzag lines, the corner's twin pair.
  EXPECT_EQ(t.segments.size(), 3u * 10);
  EXPECT_TRUE(std::count(t.segments.begin(), t.segments.end(), std::array<uint32_t, 2>{12, 17}));
}

TEST(ControlNetTopology, GBNetHasRowsSpokesAndTheCentre) {
  // Degree 3, 2 layers: each ribbon's 4 x 2 grid has 10 segments, 4 of them in each corner block
  // (shared with the neighbour, so counted twice over the ribbons), and one spoke per ribbon to
  // the centre (its two middle points are the neighbours' too): 5 * 10 - 5 * 4 + 5.
  const GBPatch d3(5, 3, test::random_points(GBPatch::point_count(5, 3), 4));
  const ControlNetTopology t3 = control_net_topology(d3);
  expect_well_formed(d3, t3, "gb d3");
  EXPECT_EQ(t3.segments.size(), 35u);
  // Degree 4, 2 layers: 5 x 2 grids with 13 segments, 4 per corner block, one middle spoke each.
  const GBPatch d4(5, 4, test::random_points(GBPatch::point_count(5, 4), 5));
  const ControlNetTopology t4 = control_net_topology(d4);
  expect_well_formed(d4, t4, "gb d4");
  EXPECT_EQ(t4.segments.size(), 5u * 13 - 5 * 4 + 5);
  int spokes = 0;
  for (const auto& s : t4.segments) spokes += s[0] == 0;
  EXPECT_EQ(spokes, 5);
  // Every boundary segment of every side is a net line.
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 4; ++j) {
      std::array<uint32_t, 2> s{uint32_t(d4.index(i, j, 0)), uint32_t(d4.index(i, j + 1, 0))};
      if (s[0] > s[1]) std::swap(s[0], s[1]);
      EXPECT_TRUE(std::count(t4.segments.begin(), t4.segments.end(), s)) << i << " " << j;
    }
}

TEST(ControlNetTopology, HermiteArrowsEndAtTheBezierHandles) {
  const auto p = asset_patch("classic/hermite.json");
  const auto& h = dynamic_cast<const HermitePatch&>(*p);
  const ControlNetTopology t = control_net_topology(h);
  expect_well_formed(h, t, "hermite");
  EXPECT_EQ(t.segments.size(), 4u);
  EXPECT_EQ(t.arrows.size(), 12u);
  EXPECT_EQ(std::count(t.is_vector.begin(), t.is_vector.end(), true), 12);
  // Side 0 (v = 0) runs from r(0,0) to r(1,0): its cubic's handles are r + r_u / 3 and
  // r(1,0) - r_u(1,0) / 3. Side 3 (u = 0) runs from r(0,1) to r(0,0).
  const std::vector<BezierCurve> sides = h.boundary_curves();
  auto tip = [&](uint32_t base, uint32_t vector) {
    for (const DerivativeArrow& a : t.arrows)
      if (a.base == base && a.vector == vector) return arrow_tip(h, a);
    ADD_FAILURE() << "no arrow " << base << " -> " << vector;
    return Vec3(0);
  };
  const double tol = 1e-12 * (1 + test::max_abs(h.r(1, 1)));
  EXPECT_LT(test::max_abs(tip(0, 8) - sides[0].control_points()[1]), tol);  // r_u(0,0)
  EXPECT_LT(test::max_abs(tip(0, 2) - sides[3].control_points()[2]), tol);  // r_v(0,0)
  // A twist arrow is r_uv / 9, the twist's share of the inner Bézier point.
  for (const DerivativeArrow& a : t.arrows)
    if (a.kind == ArrowKind::Twist) {
      EXPECT_DOUBLE_EQ(a.scale, 1.0 / 9);
    }
}

TEST(ControlNetTopology, CoonsArrowsEndAtTheBezierHandlesOfOneCell) {
  // One cell with its own parameter lengths: S = 0.7 along s, T = 1.9 along t.
  const std::vector<Vec3> data = test::random_points(16, 6);
  const CoonsNetworkPatch c(2, 2, {{0.0, 0.7}, {0.0, 0.7}}, {{0.0, 1.9}, {0.0, 1.9}}, data);
  const ControlNetTopology t = control_net_topology(c);
  expect_well_formed(c, t, "coons");
  EXPECT_EQ(t.segments.size(), 4u);
  EXPECT_EQ(t.arrows.size(), 12u);
  const std::vector<BezierCurve> sides = c.boundary_curves();
  // Side 0 (v = 0) runs from node (0,0) to (1,0): its first handle is r + r_s S / 3. Side 3
  // (u = 0) runs from node (0,1) to (0,0): its last handle is r + r_t T / 3.
  for (const DerivativeArrow& a : t.arrows) {
    if (a.base != 0) continue;
    const Vec3 tip = arrow_tip(c, a);
    if (a.vector == 1) {
      EXPECT_LT(test::max_abs(tip - sides[0].control_points()[1]), 1e-12);
    } else if (a.vector == 2) {
      EXPECT_LT(test::max_abs(tip - sides[3].control_points()[2]), 1e-12);
    } else {
      EXPECT_DOUBLE_EQ(a.scale, 0.7 * 1.9 / 9);
    }
  }
}

// A network face filled by a ribbon scheme: its sides' curves are polylines, its cross
// derivatives are vectors (never drawn as positions), and their arrows end at the ribbons' inner
// Bézier rows: the same points as the inner row of the face's GB ribbons (layer 1), which the GB
// patch of the same face holds as positions.
TEST(ControlNetTopology, RibbonArrowsEndAtTheInnerRowsOfTheFacesRibbons) {
  const Scene scene = read_scene(kAssets / "gb-hole-filling.json");
  TessellationCache cache;
  const SceneSurfaces ribbons = evaluate_scene(scene, 2, FaceScheme::SideBased, cache, "s");
  const SceneSurfaces gb = evaluate_scene(scene, 2, FaceScheme::GB, cache, "s");
  ASSERT_EQ(ribbons.surfaces.size(), gb.surfaces.size());
  std::size_t checked = 0;
  for (std::size_t f = 0; f < ribbons.surfaces.size(); ++f) {
    const Patch& p = ribbons.surfaces[f].evaluator->patch();
    const auto* g = dynamic_cast<const GBRibbonPatch*>(&gb.surfaces[f].evaluator->patch());
    ASSERT_EQ(p.type(), "ribbons");
    ASSERT_NE(g, nullptr);
    const ControlNetTopology t = control_net_topology(p);
    expect_well_formed(p, t, "face " + std::to_string(f));
    const int n = g->sides();
    ASSERT_EQ(t.arrows.size(), std::size_t(4 * n));  // cubic curves, cubic cross derivatives
    std::size_t vectors = 0;
    for (bool v : t.is_vector) vectors += v;
    EXPECT_EQ(vectors, std::size_t(4 * n));
    for (std::size_t a = 0; a < t.arrows.size(); ++a) {
      const int side = int(a / 4), j = int(a % 4);
      // The GB patch's side for the same face side.
      const auto& rs = ribbons.surfaces[f].patch_side;
      const int face_side = int(std::find(rs.begin(), rs.end(), side) - rs.begin());
      ASSERT_LT(face_side, n);
      const Vec3 inner = g->point(gb.surfaces[f].patch_side[std::size_t(face_side)], j, 1);
      EXPECT_LT(glm::length(arrow_tip(p, t.arrows[a]) - inner), 1e-12) << f << " " << a;
      ++checked;
    }
  }
  EXPECT_GT(checked, 50u);
}

}  // namespace
}  // namespace pl
