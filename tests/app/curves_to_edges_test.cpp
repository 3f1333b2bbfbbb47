// Free curves turned into network edges: curves drawn to meet become one connected chain, a face
// made from the chain is bounded by the curves exactly (cubic Béziers), a curve ending on the
// network connects to it, a closed curve becomes a loop of edges, and what cannot be done is
// refused with the curve named.
#include <gtest/gtest.h>

#include "app/document/curves_to_edges_command.hpp"
#include "app/document/network_commands.hpp"
#include "command_test_util.hpp"
#include "core/network_test_util.hpp"
#include "core/scene_curve_samples.hpp"

namespace pl::test {
namespace {

SceneCurve bezier(std::vector<Vec3> points) {
  return bezier_scene_curve(std::move(points));
}

// Four cubic Béziers around a curved quad, each ending where the next begins.
Scene four_curves() {
  Scene s;
  const Vec3 a(0, 0, 0), b(3, 0, 0.5), c(3, 3, 0), d(0, 3, 0.5);
  s.curves = {
      bezier({a, {1, -0.3, 0.3}, {2, 0.2, 0.6}, b}), bezier({b, {3.3, 1, 0.4}, {2.8, 2, 0.1}, c}),
      bezier({c, {2, 3.2, 0.2}, {1, 2.9, 0.4}, d}), bezier({d, {-0.2, 2, 0.4}, {0.3, 1, 0.2}, a})};
  return s;
}

TEST(CurvesToEdges, FourCurvesMakeAFaceBoundedExactlyByThem) {
  Document doc(four_curves());
  EXPECT_EQ(
      expect_good_command(doc, std::make_unique<CurvesToEdgesCommand>(std::vector{0, 1, 2, 3})),
      "curves 0, 1, 2, 3 to 4 network edges (exact)");
  const Scene& s = doc.scene();
  EXPECT_TRUE(s.curves.empty());
  ASSERT_TRUE(s.network);
  EXPECT_EQ(s.network->vertices.size(), 4u);  // the curves' shared ends are one vertex each
  ASSERT_EQ(s.network->edges.size(), 4u);
  const Scene curves = four_curves();
  for (int e = 0; e < 4; ++e)
    for (int k = 0; k <= 16; ++k) {
      const double t = k / 16.0;
      EXPECT_LT(glm::length(s.network->edge_curve(e).point(t) - evaluate(curves.curves[e], t).p),
                1e-14);
    }
  expect_good_command(doc, MakeFaceCommand::from_edges({0, 1, 2, 3}));
  const Network& n = *doc.scene().network;
  ASSERT_EQ(n.faces.size(), 1u);
  const NetworkTopology topo = validate_network(n, "test");
  const NetworkFilling filling = fill_network(n, topo, std::nullopt, "test");
  EXPECT_LT(max_boundary_deviation(n, topo, surfaces(filling)), 1e-13);
}

TEST(CurvesToEdges, ACurveEndingOnTheNetworkConnectsToIt) {
  Scene s = four_curves();
  Document doc(s);
  doc.execute(std::make_unique<CurvesToEdgesCommand>(std::vector{0}));
  ASSERT_EQ(doc.scene().network->vertices.size(), 2u);
  // Curve 1 (now curve 0) begins at the first curve's end, 1e-7 away: within the tolerance.
  SceneCurve next = doc.scene().curves[0];
  next.points[0] += Vec3(1e-7, 0, 0);
  Scene moved = doc.scene();
  moved.curves[0] = next;
  Document doc2(moved);
  doc2.execute(std::make_unique<CurvesToEdgesCommand>(std::vector{0}));
  const Network& n = *doc2.scene().network;
  EXPECT_EQ(n.vertices.size(), 3u);
  EXPECT_EQ(n.edges[1].v[0], n.edges[0].v[1]) << "the curves are one chain";
  // The edge begins at the vertex itself; its end tangent is the curve's.
  EXPECT_EQ(n.edge_curve(1).point(0), n.vertices[n.edges[0].v[1]]);
  EXPECT_LT(glm::length((n.edges[1].handles[0] - n.vertices[n.edges[1].v[0]]) -
                        (next.points[1] - next.points[0])),
            1e-15);
}

TEST(CurvesToEdges, AClosedCircleBecomesALoopWithinTheTolerance) {
  Scene s;
  SceneCurve c = circle_scene_curve(Vec3(0), 2);
  c.name = "rim";
  s.curves.push_back(c);
  Document doc(s);
  const std::string label =
      expect_good_command(doc, std::make_unique<CurvesToEdgesCommand>(std::vector{0}, 1e-3));
  EXPECT_NE(label.find("fitted within 0.001"), std::string::npos) << label;
  const Network& n = *doc.scene().network;
  EXPECT_GE(n.edges.size(), 3u);
  EXPECT_EQ(n.vertices.size(), n.edges.size()) << "a closed loop: as many vertices as edges";
  for (std::size_t e = 0; e < n.edges.size(); ++e)
    for (int k = 0; k <= 64; ++k)
      EXPECT_NEAR(glm::length(n.edge_curve(int(e)).point(k / 64.0)), 2.0, 1e-3);
}

TEST(CurvesToEdges, RefusesNamingTheCurve) {
  Document doc(four_curves());
  expect_refused(doc, std::make_unique<CurvesToEdgesCommand>(std::vector<int>{}), "no curve");
  expect_refused(doc, std::make_unique<CurvesToEdgesCommand>(std::vector{7}), "no curve 7");
  expect_refused(doc, std::make_unique<CurvesToEdgesCommand>(std::vector{0}, -1.0),
                 "positive number");
  // A curve whose ends are 0.05 apart, with a tolerance of 0.1: one span from a vertex to itself
  // is no edge (closed curves are cut in three, but these three would share the vertices too).
  Scene tiny;
  tiny.curves = {bezier({{0, 0, 0}, {0.02, 0.01, 0}, {0.04, 0.01, 0}, {0.05, 0, 0}})};
  tiny.curves[0].name = "tiny";
  Document doc2(tiny);
  expect_refused(doc2, std::make_unique<CurvesToEdgesCommand>(std::vector{0}, 0.1), "tiny: span");
}

}  // namespace
}  // namespace pl::test
