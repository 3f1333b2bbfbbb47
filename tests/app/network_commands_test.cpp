// The authoring commands: each leaves a valid scene, undoes and redoes bit for bit, and refuses
// invalid requests without changing anything; a network built from an empty scene with them is
// G1 everywhere with no projected vertex.
#include "app/document/network_commands.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "command_test_util.hpp"
#include "core/network/network_filling.hpp"
#include "core/network_test_util.hpp"

namespace pl::test {
namespace {

// Eight vertices in general position: a quad, a triangle and a pentagon fit on them.
const std::vector<Vec3> kPoints{{0, 0, 0},   {1, 0, 0.1},   {2, 0, 0},   {0, 1, 0.1},
                                {1, 1, 0.3}, {2.5, 1, 0.1}, {1, 2, 0.1}, {2, 2.2, 0}};

Document document_with_vertices() {
  Document doc;
  for (const Vec3& p : kPoints) doc.execute(std::make_unique<AddVertexCommand>(p));
  return doc;
}

TEST(NetworkCommands, NewSceneAndAddVertex) {
  Document doc;
  EXPECT_EQ(expect_good_command(doc, std::make_unique<AddVertexCommand>(Vec3(1, 2, 3))),
            "add vertex 0");
  ASSERT_TRUE(doc.scene().network);
  EXPECT_EQ(doc.scene().network->vertices, std::vector<Vec3>{Vec3(1, 2, 3)});
  expect_good_command(doc, std::make_unique<AddVertexCommand>(Vec3(0, 0, 1)));
  expect_refused(doc, std::make_unique<AddVertexCommand>(Vec3(0, NAN, 1)), "finite");
  expect_good_command(doc, std::make_unique<NewSceneCommand>());
  EXPECT_FALSE(doc.scene().network);
  EXPECT_EQ(scene_to_json(doc.scene()), scene_to_json(Scene{}));
}

TEST(NetworkCommands, AddEdgePutsHandlesOnTheChordThenInTheTangentPlanes) {
  Document doc = document_with_vertices();
  expect_good_command(doc, std::make_unique<AddEdgeCommand>(0, 1));
  const Network& n = *doc.scene().network;
  const Vec3 a = n.vertices[0], b = n.vertices[1];
  EXPECT_LT(glm::length(n.edges[0].handles[0] - (a + (b - a) / 3.0)), 1e-15);
  EXPECT_LT(glm::length(n.edges[0].handles[1] - (b - (b - a) / 3.0)), 1e-15);
  // Vertex 4 gets a fixed normal: a new edge's handle there lies in its plane, a third of the
  // chord away.
  expect_good_command(doc, std::make_unique<SetVertexNormalCommand>(4, Vec3(0.1, -0.2, 1)));
  EXPECT_EQ(expect_good_command(doc, std::make_unique<AddEdgeCommand>(4, 2)),
            "add edge 1 (vertices 4 and 2)");
  const Network& m = *doc.scene().network;
  const Vec3 normal = *m.normals[4];
  EXPECT_LT(glm::length(normal - glm::normalize(Vec3(0.1, -0.2, 1))), 1e-15);
  const Vec3 t = m.edges[1].handles[0] - m.vertices[4];
  EXPECT_LT(std::fabs(glm::dot(t, normal)), 1e-15);
  EXPECT_NEAR(glm::length(t), glm::length(m.vertices[2] - m.vertices[4]) / 3, 1e-15);
  // Two edges at vertex 1 span its plane: a third one is turned into it.
  expect_good_command(doc, std::make_unique<AddEdgeCommand>(1, 2));
  expect_good_command(doc, std::make_unique<AddEdgeCommand>(1, 5));
  const Network& k = *doc.scene().network;
  const Vec3 plane = glm::normalize(
      glm::cross(k.edges[0].handles[1] - k.vertices[1], k.edges[2].handles[0] - k.vertices[1]));
  EXPECT_LT(std::fabs(glm::dot(k.edges[3].handles[0] - k.vertices[1], plane)), 1e-14);

  expect_refused(doc, std::make_unique<AddEdgeCommand>(3, 3), "two different vertices");
  expect_refused(doc, std::make_unique<AddEdgeCommand>(1, 0), "already joined by edge 0");
  expect_refused(doc, std::make_unique<AddEdgeCommand>(1, 42), "vertex 42 does not exist");
  Document empty;
  expect_refused(empty, std::make_unique<AddEdgeCommand>(0, 1), "no curve network");
}

TEST(NetworkCommands, MakeFaceCreatesMissingEdgesAndAgreesWithItsNeighbours) {
  Document doc = document_with_vertices();
  // No neighbour: the face faces `towards`. Given clockwise seen from +z, it is turned round.
  EXPECT_EQ(expect_good_command(
                doc, std::make_unique<MakeFaceCommand>(std::vector{0, 3, 4, 1}, Vec3(0, 0, 1))),
            "make face 0 (4 sides, 4 new edges)");
  EXPECT_EQ(doc.scene().network->faces[0].loop, (std::vector{0, 1, 4, 3}));
  // A neighbour decides: the loop given the other way round is turned to run 4 -> 1.
  expect_good_command(doc, std::make_unique<MakeFaceCommand>(std::vector{1, 4, 2}));
  EXPECT_EQ(doc.scene().network->faces[1].loop, (std::vector{1, 2, 4}));
  // A pentagon on the triangle's edge 4-2, which it runs the other way.
  expect_good_command(doc, std::make_unique<MakeFaceCommand>(std::vector{4, 2, 5, 7, 6}));
  const Network& n = *doc.scene().network;
  EXPECT_EQ(n.faces.size(), 3u);
  EXPECT_EQ(n.edges.size(), 10u);
  EXPECT_NO_THROW(validate_network(n, "test"));
  // Every vertex's end tangents share a plane, so the filling is G1 without projecting any.
  const Continuity c = filled_continuity(n);
  EXPECT_LT(c.angle_deg, 1e-6);
  EXPECT_EQ(c.projected, 0u);

  // A face from a closed chain of edges: delete the pentagon, make it from its five edges.
  std::vector<int> edges;
  for (std::size_t i = 0; i < n.faces[2].loop.size(); ++i)
    edges.push_back(edge_between(n, n.faces[2].loop[i], n.faces[2].loop[(i + 1) % 5]));
  const std::vector<int> loop = n.faces[2].loop;
  expect_good_command(doc, delete_face_command(2));
  std::reverse(edges.begin(), edges.end());
  expect_good_command(doc, MakeFaceCommand::from_edges(edges));
  const std::vector<int>& again = doc.scene().network->faces[2].loop;
  ASSERT_EQ(again.size(), loop.size());
  const auto start = std::find(again.begin(), again.end(), loop[0]) - again.begin();
  for (std::size_t i = 0; i < loop.size(); ++i)  // the same cycle, the same direction
    EXPECT_EQ(again[(start + i) % again.size()], loop[i]);

  // Refusals.
  expect_refused(doc, MakeFaceCommand::from_edges({0, 1, 2}), "closed chain");
  expect_refused(doc, MakeFaceCommand::from_edges({0, 1}), "at least 3 edges");
  expect_refused(doc, std::make_unique<MakeFaceCommand>(std::vector{0, 1, 0, 3}), "appears twice");
  expect_refused(doc, std::make_unique<MakeFaceCommand>(std::vector{0, 1}), "at least 3");
  expect_refused(doc, std::make_unique<MakeFaceCommand>(std::vector{0, 1, 4, 3}),
                 "already has these vertices");
  // Edge 1-4 already joins the quad and the triangle: a third face on it is refused.
  expect_refused(doc, std::make_unique<MakeFaceCommand>(std::vector{1, 4, 7}), "at most two faces");
}

TEST(NetworkCommands, FillHolesClosesEveryBoundaryLoopOfThreeToTwelveSides) {
  Scene s;
  s.network = sphere_blob(false);  // open at the bottom: a five-sided hole
  Document doc(s);
  EXPECT_EQ(expect_good_command(doc, std::make_unique<FillHolesCommand>()), "fill hole: face 10");
  const Network& n = *doc.scene().network;
  EXPECT_EQ(n.faces.back().loop.size(), 5u);
  const Continuity c = filled_continuity(n);
  EXPECT_LT(c.angle_deg, 1e-6);
  EXPECT_EQ(c.projected, 0u);
  expect_refused(doc, std::make_unique<FillHolesCommand>(), "no closed loop");
  // The hole has five sides: not filled when at most four are asked for.
  Document small(s);
  expect_refused(small, std::make_unique<FillHolesCommand>(4), "no closed loop");
}

TEST(NetworkCommands, DeleteKeepsTheNetworkValidAndIndicesConsistent) {
  Scene s;
  s.network = sphere_blob(true);
  Document doc(s);
  const Network before = *doc.scene().network;
  // The apex: its five edges and five triangles go; everything else is renumbered.
  EXPECT_EQ(expect_good_command(doc, delete_vertex_command(0)),
            "delete vertex 0, edges 0, 4, 8, 12 and 16, faces 0, 2, 4, 6 and 8");
  const Network& n = *doc.scene().network;
  EXPECT_EQ(n.vertices.size(), before.vertices.size() - 1);
  EXPECT_EQ(n.edges.size(), before.edges.size() - 5);
  EXPECT_EQ(n.faces.size(), before.faces.size() - 5);
  EXPECT_EQ(n.vertices[0], before.vertices[1]);
  EXPECT_EQ(n.faces[0].loop, (std::vector{0, 5, 6, 1}));  // was 1, 6, 7, 2
  Network holes = n;  // the five apex triangles leave one five-sided hole
  EXPECT_EQ(fill_holes(holes), std::vector<int>{int(n.faces.size())});
  // An edge takes its two faces with it; a face goes alone.
  expect_good_command(doc, delete_edge_command(0));
  expect_good_command(doc, delete_face_command(0));
  expect_refused(doc, delete_face_command(99), "face 99 does not exist");
  expect_refused(doc, delete_edge_command(-1), "edge -1 does not exist");
  expect_refused(doc, delete_vertex_command(1000), "vertex 1000 does not exist");
  // Several at once.
  expect_good_command(
      doc, std::make_unique<DeleteCommand>(std::vector{0, 3}, std::vector{2}, std::vector<int>{}));
}

TEST(NetworkCommands, SplitEdgeKeepsTheCurveAndGivesItsFacesASide) {
  Scene s;
  s.network = sphere_blob(true);
  Document doc(s);
  const Network before = *doc.scene().network;
  const int e = 5;  // a ring edge between a triangle and a quad
  const BezierCurve curve = before.edge_curve(e);
  const std::string label = expect_good_command(doc, std::make_unique<SplitEdgeCommand>(e, 0.3));
  const Network& n = *doc.scene().network;
  EXPECT_NE(label.find("now has 5 sides (GB)"), std::string::npos) << label;
  EXPECT_NE(label.find("now has 4 sides (Gregory)"), std::string::npos) << label;
  // de Casteljau: the two edges trace the old curve.
  const int v = int(before.vertices.size()), e2 = int(before.edges.size());
  const BezierCurve left = n.edge_curve(e), right = n.edge_curve(e2);
  double worst = 0;
  for (int k = 0; k <= 100; ++k) {
    const double u = k / 100.0;
    worst = std::max(worst, glm::length(left.point(u) - curve.point(0.3 * u)));
    worst = std::max(worst, glm::length(right.point(u) - curve.point(0.3 + 0.7 * u)));
  }
  EXPECT_LT(worst, 1e-15);
  EXPECT_EQ(n.vertices[v], curve.point(0.3));
  int faces_with_v = 0;
  for (const NetworkFace& f : n.faces) faces_with_v += std::count(f.loop.begin(), f.loop.end(), v);
  EXPECT_EQ(faces_with_v, 2);
  ASSERT_FALSE(n.normals.empty());
  EXPECT_TRUE(n.normals[v].has_value());
  const Continuity c = filled_continuity(n);
  EXPECT_LT(c.angle_deg, 1e-6);
  EXPECT_EQ(c.projected, 0u);
  expect_refused(doc, std::make_unique<SplitEdgeCommand>(e, 1.0), "between 0 and 1");
  expect_refused(doc, std::make_unique<SplitEdgeCommand>(e, 0.0), "between 0 and 1");
  expect_refused(doc, std::make_unique<SplitEdgeCommand>(999, 0.5), "does not exist");
}

TEST(NetworkCommands, SchemesNamesAndNormals) {
  Scene s;
  s.network = sphere_blob(true);
  Document doc(s);
  EXPECT_EQ(expect_good_command(doc, std::make_unique<SetFaceSchemeCommand>(1, FaceScheme::GB)),
            "face 1 scheme gb");
  EXPECT_EQ(expect_good_command(doc, std::make_unique<SetFaceNameCommand>(1, "side")),
            "rename face 1");
  EXPECT_EQ(doc.scene().network->faces[1].name, "side");
  const std::string face_3 = doc.scene().network->faces.at(3).name;
  EXPECT_EQ(expect_good_command(doc, std::make_unique<SetEdgeNameCommand>(3, "rim")),
            "rename edge 3");
  EXPECT_EQ(doc.scene().network->edges[3].name, "rim");
  EXPECT_EQ(doc.scene().network->faces[3].name, face_3);  // an edge's rename names no face
  expect_refused(doc, std::make_unique<SetEdgeNameCommand>(99, "x"), "edge 99 does not exist");
  // A split turns face 1 into a pentagon: Gregory is refused there.
  expect_good_command(doc, std::make_unique<SplitEdgeCommand>(3, 0.5));
  expect_refused(doc, std::make_unique<SetFaceSchemeCommand>(1, FaceScheme::Gregory),
                 "a Gregory patch has 3 or 4");
  expect_refused(doc, std::make_unique<SetFaceNameCommand>(77, "x"), "face 77 does not exist");

  // A fixed normal turns the vertex's handles with its plane: still G1, nothing projected.
  EXPECT_EQ(
      expect_good_command(doc, std::make_unique<SetVertexNormalCommand>(0, Vec3(0.2, 0.1, 1))),
      "fix the tangent plane of vertex 0");
  const Network& n = *doc.scene().network;
  const Vec3 normal = *n.normals[0];
  EXPECT_LT(glm::length(normal - glm::normalize(Vec3(0.2, 0.1, 1))), 1e-15);
  for (int e : edges_at(n, 0)) EXPECT_LT(std::fabs(glm::dot(end_tangent(n, e, 0), normal)), 1e-14);
  Continuity c = filled_continuity(n);
  EXPECT_LT(c.angle_deg, 1e-6);
  EXPECT_EQ(c.projected, 0u);
  // Back to fitted: the handles stay, and the fitted plane is the one they lie in.
  expect_good_command(doc, std::make_unique<SetVertexNormalCommand>(0, std::nullopt));
  EXPECT_FALSE(doc.scene().network->normals[0].has_value());
  c = filled_continuity(*doc.scene().network);
  EXPECT_LT(c.angle_deg, 1e-6);
  EXPECT_EQ(c.projected, 0u);
  expect_refused(doc, std::make_unique<SetVertexNormalCommand>(0, Vec3(0)), "non-zero");
}

// The flow of the editor's end-to-end authoring test, through the commands alone: from an empty
// scene to a triangle, a quad and a pentagon; a turned tangent plane, a split edge, a face
// deleted and made again, a scheme changed; the saved file is G1 with no projected vertex, and
// undoing to the empty scene and redoing gives the same file byte for byte.
TEST(NetworkCommands, AnAuthoringSessionIsG1AndReplaysByteForByte) {
  TempDir dir;
  Document doc;
  for (const Vec3& p : kPoints) doc.execute(std::make_unique<AddVertexCommand>(p));
  doc.execute(std::make_unique<MakeFaceCommand>(std::vector{0, 1, 4, 3}, Vec3(0, 0, 1)));
  doc.execute(std::make_unique<MakeFaceCommand>(std::vector{1, 2, 4}));
  doc.execute(std::make_unique<MakeFaceCommand>(std::vector{4, 2, 5, 7, 6}));
  doc.execute(std::make_unique<SetVertexNormalCommand>(4, Vec3(-0.1, 0.15, 1)));
  const std::string split = doc.execute(
      std::make_unique<SplitEdgeCommand>(edge_between(*doc.scene().network, 0, 1), 0.4));
  EXPECT_NE(split.find("now has 5 sides (GB)"), std::string::npos) << split;
  doc.execute(delete_face_command(1));
  doc.execute(std::make_unique<MakeFaceCommand>(std::vector{1, 2, 4}));
  doc.execute(std::make_unique<SetFaceSchemeCommand>(2, FaceScheme::GB));
  const Network& n = *doc.scene().network;
  EXPECT_GE(n.vertices.size(), 7u);
  EXPECT_GE(n.edges.size(), 9u);
  std::vector<std::size_t> sides;
  for (const NetworkFace& f : n.faces) sides.push_back(f.loop.size());
  std::sort(sides.begin(), sides.end());
  EXPECT_EQ(sides, (std::vector<std::size_t>{3, 5, 5}));  // the quad gained a side
  const auto path = dir / "authored.json";
  doc.save_as(path);
  const std::string saved = slurp(path);
  // What `patchlab analyze` reports on the saved file.
  const CliResult r = cli({"analyze", path.string(), "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto report = nlohmann::json::parse(r.out);
  ASSERT_EQ(report["edges"].size(), 2u);  // the triangle's edges with the quad and the pentagon
  for (const auto& e : report["edges"]) EXPECT_LT(e["max_normal_angle_deg"].get<double>(), 1e-6);
  EXPECT_TRUE(report["vertices"].empty());
  const Continuity c = filled_continuity(n);
  EXPECT_LT(c.angle_deg, 1e-6);
  EXPECT_EQ(c.projected, 0u);

  while (doc.undo()) {
  }
  EXPECT_EQ(scene_to_json(doc.scene()), scene_to_json(Scene{}));
  while (doc.redo()) {
  }
  const auto again = dir / "again.json";
  doc.save_as(again);
  EXPECT_EQ(slurp(again), saved);
}

}  // namespace
}  // namespace pl::test
