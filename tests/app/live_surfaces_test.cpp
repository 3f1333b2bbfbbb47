// LiveSurfaces refreshes only what an edit touched: after drags, typed moves and topology edits
// its meshes, control points and network curves are those of a fresh LiveSurfaces.
#include "app/editor/logic/live_surfaces.hpp"

#include <gtest/gtest.h>

#include "render/draw_scene_builder.hpp"
#include "app/document/document.hpp"
#include "app/document/network_commands.hpp"
#include "core/network/sample_networks.hpp"

namespace pl::test {
namespace {

void expect_same(const LiveSurfaces& live, const Scene& scene) {
  const LiveSurfaces fresh(scene, live.density(), live.scheme(), "fresh");
  const DrawScene &a = live.draw(), &b = fresh.draw();
  ASSERT_EQ(a.surfaces.size(), b.surfaces.size());
  for (std::size_t i = 0; i < a.surfaces.size(); ++i) {
    EXPECT_EQ(a.surfaces[i].name, b.surfaces[i].name) << i;
    EXPECT_EQ(a.surfaces[i].triangles, b.surfaces[i].triangles) << i;
    ASSERT_EQ(a.surfaces[i].positions.size(), b.surfaces[i].positions.size()) << i;
    for (std::size_t k = 0; k < a.surfaces[i].positions.size(); ++k)
      ASSERT_LT(glm::length(a.surfaces[i].positions[k] - b.surfaces[i].positions[k]), 1e-12)
          << i << " " << k;
    EXPECT_EQ(a.surfaces[i].revision, live.surfaces().surfaces[i].evaluator->revision());
  }
  EXPECT_EQ(live.points().positions, fresh.points().positions);
  EXPECT_EQ(live.points().kinds, fresh.points().kinds);
  EXPECT_EQ(live.points().refs, fresh.points().refs);
  EXPECT_EQ(live.points().segments, fresh.points().segments);
  EXPECT_EQ(a.net.points, b.net.points);
  EXPECT_EQ(a.net.kinds, b.net.kinds);
  EXPECT_EQ(a.network_curves, b.network_curves);
}

TEST(LiveSurfaces, DragsAndTopologyEditsRefreshOnlyWhatTheyTouched) {
  Scene s;
  s.network = cube_sphere_network(2, FaceScheme::GB);
  Document doc(s);
  LiveSurfaces live(doc.scene(), 5, std::nullopt, "live", doc.revision());
  const std::vector<SurfaceMesh> before = live.draw().surfaces;
  // A vertex drag: its four faces change, the other meshes are the same objects' revisions.
  doc.begin_drag({PointRef::vertex(4)});
  for (int i = 1; i <= 3; ++i) {
    doc.drag_to({doc.scene().network->vertices[4] + Vec3(0.01, 0, 0)});
    const std::vector<int> changed = live.sync(doc.scene(), doc.revision());
    EXPECT_EQ(changed.size(), 4u);
  }
  doc.end_drag();
  expect_same(live, doc.scene());
  int same = 0;
  for (std::size_t i = 0; i < before.size(); ++i)
    same += live.draw().surfaces[i].revision == before[i].revision;
  EXPECT_EQ(same, int(before.size()) - 4);
  // A handle drag, a typed move, a normal.
  doc.begin_drag({PointRef::handle(7, 1)});
  doc.drag_to({doc.scene().network->edges[7].handles[1] + Vec3(0, 0.02, 0.01)});
  live.sync(doc.scene(), doc.revision());
  doc.end_drag();
  expect_same(live, doc.scene());
  doc.execute(std::make_unique<SetVertexNormalCommand>(2, Vec3(0.1, 0.2, 1)));
  live.sync(doc.scene(), doc.revision());
  expect_same(live, doc.scene());
  // Topology: delete a face, split an edge, undo, redo.
  doc.execute(delete_face_command(3));
  live.sync(doc.scene(), doc.revision());
  expect_same(live, doc.scene());
  doc.execute(std::make_unique<SplitEdgeCommand>(10, 0.5));
  live.sync(doc.scene(), doc.revision());
  expect_same(live, doc.scene());
  doc.undo();
  doc.undo();
  live.sync(doc.scene(), doc.revision());
  expect_same(live, doc.scene());
  doc.redo();
  live.sync(doc.scene(), doc.revision());
  expect_same(live, doc.scene());
}

TEST(LiveSurfaces, DensitiesPerSurface) {
  Scene s;
  s.network = cube_sphere_network(2);
  LiveSurfaces live(s, 6, std::nullopt, "live");
  std::vector<int> d = live.densities();
  EXPECT_EQ(d, std::vector<int>(24, 6));
  d[5] = 3;
  EXPECT_EQ(live.set_densities(d), std::vector<int>{5});
  EXPECT_EQ(live.densities(), d);
  EXPECT_EQ(live.draw().surfaces[5].positions.size(),
            live.surfaces().surfaces[5].evaluator->sample_count());
  EXPECT_LT(live.sample_count(), 24 * live.draw().surfaces[0].positions.size());
}

TEST(LiveSurfaces, NetworkCurvesWithFewerSegmentsStaySoThroughDrags) {
  Scene s;
  s.network = cube_sphere_network(2);
  Document doc(s);
  LiveSurfaces live(doc.scene(), 4, std::nullopt, "live", doc.revision());
  const std::size_t edges = doc.scene().network->edges.size();
  std::vector<int> segments(edges, 8);
  segments[0] = 16;
  EXPECT_TRUE(live.set_curve_segments(segments));
  EXPECT_FALSE(live.set_curve_segments(segments));  // nothing to do
  doc.begin_drag({PointRef::vertex(4)});
  doc.drag_to({doc.scene().network->vertices[4] + Vec3(0.02, 0, 0)});
  live.sync(doc.scene(), doc.revision());
  doc.end_drag();
  for (std::size_t e = 0; e < edges; ++e)
    EXPECT_EQ(live.draw().network_curves[e],
              edge_polyline(*doc.scene().network, int(e), segments[e]))
        << e;
  EXPECT_FALSE(live.set_curve_segments(std::vector<int>(3, 8)));  // not one per edge
}

}  // namespace
}  // namespace pl::test
