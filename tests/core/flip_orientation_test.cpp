// Flipping a patch's orientation: the flipped patch is the same surface point for point (at the
// reflected domain point) with the opposite normal, its points are a permutation of the old ones,
// and the types that cannot be flipped say so.
#include "core/patch/flip_orientation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "core/domain/convex_polygon.hpp"
#include "core/io/scene_io.hpp"
#include "core/patch/bezier_patch.hpp"
#include "core/patch/gb/gb_patch.hpp"
#include "core/patch/gb/gb_ribbon_patch.hpp"
#include "core/patch/gregory_quad.hpp"
#include "core/patch/gregory_tri.hpp"
#include "test_util.hpp"

namespace pl {
namespace {

const std::filesystem::path kAssets = std::filesystem::path(PATCHLAB_SOURCE_DIR) / "assets";

std::shared_ptr<Patch> asset_patch(const std::string& file) {
  const Scene s = read_scene(kAssets / file);
  if (s.patches.empty()) throw std::runtime_error(file + " has no explicit patch");
  return s.patches.front().patch;
}

Vec3 unit_normal(const SurfaceJet& s) {
  return glm::normalize(glm::cross(s.su, s.sv));
}

// Interior samples of the unit square (also inside the unit triangle when triangle is set).
std::vector<Vec2> square_samples(bool triangle = false) {
  std::vector<Vec2> xs;
  for (int i = 1; i < 8; ++i)
    for (int j = 1; j < 8; ++j) {
      const Vec2 x(i / 8.0 + 0.013 * j, j / 8.0 - 0.011 * i);
      if (!triangle || x.x + x.y < 0.97) xs.push_back(x);
    }
  return xs;
}

// Worst position and normal mismatch of flipped(reflect(x)) against -original(x).
void expect_flipped(const Patch& original, const std::vector<Vec2>& xs,
                    const std::function<Vec2(Vec2)>& reflect, const std::string& what) {
  const FlippedPatch f = flipped_orientation(original);
  ASSERT_TRUE(f.patch);
  EXPECT_EQ(f.patch->type(), original.type()) << what;
  ASSERT_EQ(f.old_index.size(), original.size()) << what;
  std::vector<std::size_t> sorted = f.old_index;
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t k = 0; k < sorted.size(); ++k) ASSERT_EQ(sorted[k], k) << what;
  for (std::size_t k = 0; k < f.patch->size(); ++k)
    EXPECT_EQ(f.patch->control_point(k), original.control_point(f.old_index[k])) << what;

  double scale = 0;
  for (const Vec3& p : original.control_points()) scale = std::max(scale, test::max_abs(p));
  double position = 0, normal = 0;
  for (const Vec2& x : xs) {
    const SurfaceJet a = original.evaluate(x), b = f.patch->evaluate(reflect(x));
    position = std::max(position, test::max_abs(a.p - b.p) / (1 + scale));
    normal = std::max(normal, test::max_abs(unit_normal(a) + unit_normal(b)));
  }
  EXPECT_LT(position, 1e-12) << what;
  EXPECT_LT(normal, 1e-9) << what;
}

Vec2 swap_uv(Vec2 x) {
  return {x.y, x.x};
}

TEST(FlipOrientation, SquareTypesAreTransposed) {
  for (const char* file :
       {"bezier-wave.json", "classic/bspline.json", "classic/nurbs.json",
        "classic/interpolating.json", "classic/hermite.json", "classic/coons-network.json"}) {
    const auto p = asset_patch(file);
    ASSERT_TRUE(can_flip_orientation(*p)) << file;
    expect_flipped(*p, square_samples(), swap_uv, file);
  }
}

TEST(FlipOrientation, GregoryPatchesAreMirrored) {
  const GregoryQuadPatch quad(test::random_points(20, 3));
  expect_flipped(quad, square_samples(), swap_uv, "gregory-quad");
  const GregoryTriPatch tri(test::random_points(18, 4));
  // The unit triangle (A, B, C) = ((0,0), (1,0), (0,1)) mirrored about its diagonal swaps B, C.
  expect_flipped(tri, square_samples(true), swap_uv, "gregory-tri");
}

TEST(FlipOrientation, GBPatchIsMirroredAboutVertexZero) {
  for (const auto& [n, d] : {std::pair{5, 3}, {5, 4}, {3, 5}, {6, 2}, {4, 1}}) {
    const GBPatch gb(n, d, test::random_points(GBPatch::point_count(n, d), 10 + n * d));
    // The domain is its own mirror image: vertex m goes to vertex -m, so the mirror line runs
    // through the centre and vertex 0.
    const ConvexPolygonDomain& dom = gb.polygon();
    Vec2 c(0);
    for (int m = 0; m < n; ++m) c += dom.side_point(m, 0) / double(n);
    const Vec2 axis = glm::normalize(dom.side_point(1, 0) - c);  // side 1 starts at vertex 0
    auto reflect = [&](Vec2 x) {
      const Vec2 r = x - c;
      return c + 2 * glm::dot(r, axis) * axis - r;
    };
    std::vector<Vec2> xs;
    for (int m = 0; m < n; ++m)
      for (double a : {0.15, 0.5, 0.85})
        for (double t : {0.2, 0.55}) xs.push_back(c + a * (dom.side_point(m, t) - c));
    expect_flipped(gb, xs, reflect, "gb " + std::to_string(n) + "-gon degree " + std::to_string(d));
  }
}

TEST(FlipOrientation, GBRibbonPatchIsMirrored) {
  // An L: concave, with ribbons of different degrees and layer counts per side.
  const ConcavePolygonDomain dom({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}});
  std::vector<std::vector<std::vector<Vec3>>> ribbons(dom.side_count());
  std::vector<Vec3> pool = test::random_points(200, 8, 0.2);
  std::size_t next = 0;
  for (int i = 0; i < dom.side_count(); ++i) {
    const int d = 3 + i % 2, l = 2 + i % 2;
    for (int k = 0; k < l; ++k) {
      std::vector<Vec3> row;
      for (int j = 0; j <= d; ++j) {
        const Vec2 q = dom.side_point(i, double(j) / d);
        row.push_back(Vec3(q, 0.0) + (k == 0 && (j == 0 || j == d) ? Vec3(0) : pool[next++]));
      }
      ribbons[i].push_back(row);
    }
  }
  // Shared corners: each ribbon's last boundary point is the next one's first.
  for (int i = 0; i < dom.side_count(); ++i)
    ribbons[(i + 1) % dom.side_count()][0].front() = ribbons[i][0].back();
  const GBRibbonPatch g(dom, ribbons);
  const std::vector<Vec2> xs = {{0.3, 0.3}, {1.5, 0.5}, {0.5, 1.5}, {0.8, 0.8}, {1.2, 0.2}};
  expect_flipped(
      g, xs, [](Vec2 x) { return Vec2(-x.x, x.y); }, "gb-ribbons");
}

TEST(FlipOrientation, CatmullClarkFacesAreReversed) {
  const auto p = asset_patch("classic/catmull-clark.json");
  const FlippedPatch f = flipped_orientation(*p);
  const auto before = p->surface_pieces(), after = f.patch->surface_pieces();
  ASSERT_EQ(before.size(), after.size());
  // A quad (v0, v1, v2, v3) reversed is (v3, v2, v1, v0): its ptex (u, v) becomes (u, 1 - v).
  double position = 0, normal = 0;
  for (std::size_t i = 0; i < before.size(); ++i)
    for (const Vec2& x : square_samples()) {
      const SurfaceJet a = before[i]->evaluate(x), b = after[i]->evaluate({x.x, 1 - x.y});
      position = std::max(position, test::max_abs(a.p - b.p));
      normal = std::max(normal, test::max_abs(unit_normal(a) + unit_normal(b)));
    }
  EXPECT_LT(position, 1e-9);
  EXPECT_LT(normal, 1e-7);
}

TEST(FlipOrientation, FlippingTwiceRestoresThePoints) {
  for (const char* file :
       {"bezier-wave.json", "classic/nurbs.json", "classic/coons-network.json"}) {
    const auto p = asset_patch(file);
    const FlippedPatch twice = flipped_orientation(*flipped_orientation(*p).patch);
    EXPECT_EQ(twice.patch->control_points(), p->control_points()) << file;
  }
  const GBPatch gb(5, 4, test::random_points(GBPatch::point_count(5, 4), 2));
  EXPECT_EQ(flipped_orientation(*flipped_orientation(gb).patch).patch->control_points(),
            gb.control_points());
}

TEST(FlipOrientation, CompositeTypesAreRefusedByName) {
  for (const char* file : {"classic/pair-join.json", "classic/gap-fill.json"}) {
    const auto p = asset_patch(file);
    EXPECT_FALSE(can_flip_orientation(*p)) << file;
    try {
      flipped_orientation(*p);
      ADD_FAILURE() << file << " was flipped";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(p->type()), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace pl
