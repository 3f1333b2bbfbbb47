// What `patchlab render` hands the renderer: every patch type's net lines, derivative data as
// arrows (not as points), network faces' points derived and joined to the network's own points,
// and a patch drawn as several surfaces (Catmull–Clark) netted once.
#include <gtest/gtest.h>

#include <set>

#include "core/patch/control_net_topology.hpp"
#include "render/point_key.hpp"
#include "render_test_util.hpp"

namespace pl {
namespace {

TEST(DrawSceneBuilder, NetworkFacePointsAreDerivedAndShareTheNetworksPoints) {
  const Scene scene = load_scene_file(test::asset("default.json"));
  const DrawScene d = test::file_draw_scene(test::asset("default.json"));
  const Network& net = *scene.network;
  const std::size_t network_points = net.vertices.size() + 2 * net.edges.size();
  ASSERT_EQ(d.net.roles.size(), d.net.points.size());
  // The network's vertices and handles first, editable; then only derived points, none of them
  // at the place of a network point (face boundaries join the network's points).
  std::set<std::array<double, 3>> editable;
  for (std::size_t i = 0; i < d.net.points.size(); ++i) {
    const Vec3& p = d.net.points[i];
    if (i < network_points) {
      EXPECT_EQ(d.net.role(i), PointRole::Editable) << i;
      editable.insert({p.x, p.y, p.z});
    } else {
      EXPECT_EQ(d.net.role(i), PointRole::Derived) << i;
      EXPECT_FALSE(editable.count({p.x, p.y, p.z})) << "point " << i << " doubles a network point";
    }
  }
  EXPECT_GT(d.net.points.size(), network_points);  // twins and ribbon rows
  // Net lines reach the derived points: each is on at least one segment.
  std::vector<int> degree(d.net.points.size(), 0);
  for (const auto& s : d.net.segments) ++degree[s[0]], ++degree[s[1]];
  for (std::size_t i = network_points; i < d.net.points.size(); ++i) EXPECT_GT(degree[i], 0) << i;
  const PointKeyEntries key = PointKeyEntries::of(d);
  EXPECT_TRUE(key.point_styles &
              (1u << point_style_tag(ControlPointKind::Twin, PointRole::Derived)));
  EXPECT_EQ(key.arrow_kinds, 0u);
}

TEST(DrawSceneBuilder, HermiteDerivativesAreArrowsNotPoints) {
  const Scene scene = load_scene_file(test::asset("classic/hermite.json"));
  const DrawScene d = test::file_draw_scene(test::asset("classic/hermite.json"));
  const Patch& p = *scene.patches.at(0).patch;
  // Four corner positions; twelve arrows from them (two tangents and a twist per corner).
  EXPECT_EQ(d.net.points.size(), 4u);
  EXPECT_EQ(d.net.segments.size(), 4u);
  ASSERT_EQ(d.arrows.size(), 12u);
  for (const Arrow& a : d.arrows) {
    bool at_corner = false;
    for (const Vec3& c : d.net.points) at_corner |= a.base == c;
    EXPECT_TRUE(at_corner);
  }
  // The points are the positions (no dots at the vectors' own coordinates), and the arrows are
  // the topology's: base plus scale times vector.
  const ControlNetTopology t = control_net_topology(p);
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (!t.is_vector[i]) {
      EXPECT_EQ(d.net.points.at(k++), p.control_point(i));
    }
  for (std::size_t i = 0; i < t.arrows.size(); ++i)
    EXPECT_EQ(d.arrows[i].tip, arrow_tip(p, t.arrows[i]));
}

TEST(DrawSceneBuilder, ACatmullClarkSurfaceIsNettedOnce) {
  const Scene scene = load_scene_file(test::asset("classic/catmull-clark.json"));
  const DrawScene d = test::file_draw_scene(test::asset("classic/catmull-clark.json"));
  const Patch& p = *scene.patches.at(0).patch;
  EXPECT_GT(d.surfaces.size(), 1u);  // one surface per base face
  EXPECT_EQ(d.net.points.size(), p.size());
  EXPECT_EQ(d.net.segments.size(), control_net_topology(p).segments.size());
}

TEST(DrawSceneBuilder, EveryExplicitPatchTypeHasNetLines) {
  for (const char* file :
       {"bezier-wave.json", "classic/bspline.json", "classic/nurbs.json",
        "classic/interpolating.json", "classic/coons-network.json", "classic/pair-join.json",
        "classic/gap-fill.json", "classic/catmull-clark-ngon.json"}) {
    const DrawScene d = test::file_draw_scene(test::asset(file));
    EXPECT_GE(d.net.segments.size(), d.net.points.size() - 1) << file;
  }
}

}  // namespace
}  // namespace pl
