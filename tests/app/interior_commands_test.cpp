// The free interior points of network GB faces as document points, and the commands on a face's
// interior: a free point's position is its default (the default-net rule on the face's G1 data,
// computed here independently from the whole network's ribbons) plus its stored offset; moving
// it stores the difference; the degree and reset commands undo bit for bit and refuse without
// changing anything.
#include "app/document/interior_commands.hpp"

#include <gtest/gtest.h>

#include "app/document/network_commands.hpp"
#include "command_test_util.hpp"
#include "core/network/face_ribbons.hpp"
#include "core/network/gb_face.hpp"
#include "core/network/gb_face_free_points.hpp"
#include "core/network/gb_face_interior.hpp"
#include "core/network/network_filling.hpp"
#include "core/patch/gb/default_net.hpp"

namespace pl::test {
namespace {

Scene asset(const std::string& name) {
  return read_scene(std::filesystem::path(PATCHLAB_SOURCE_DIR) / "assets" / name);
}

// The default position of free point `name` of face f as the whole network's filling has it:
// the stored default of the face's interior patch (fill_network), or for a face filled without
// one, the default net of its ribbons (build_face_ribbons).
Vec3 reference_default(const Scene& s, int f, const InteriorOffset& name) {
  const Network& net = *s.network;
  const NetworkTopology topo = validate_network(net, "test");
  const NetworkFace& face = net.faces[f];
  const std::size_t k = interior_point_index(int(face.loop.size()), face.degree, name);
  const NetworkFilling filling = fill_network(net, topo, std::nullopt, "test");
  if (const auto* p = dynamic_cast<const GBInteriorPatch*>(filling.faces[f].patch.get())) {
    EXPECT_TRUE(p->is_free(k));
    return p->control_point(p->default_index(k));
  }
  std::vector<ProjectedVertex> projected;
  return gb_face_default_net(build_face_ribbons(net, topo, projected)[f], face.degree)[k];
}

TEST(InteriorPoints, NamesDescribeAndExistence) {
  EXPECT_EQ(describe(PointRef::free_point(2, {.side = 1, .j = 2, .layer = 2})),
            "face 2 free point [1,2,2]");
  EXPECT_EQ(describe(PointRef::free_point(2, {.centre = true})), "face 2 centre");
  // Degree 6 pentagon: per side j = 2, 3 of layer 2, and the centre (docs/scene-format.md).
  EXPECT_EQ(gb_face_free_point_names(5, 6).size(), 11u);
  EXPECT_EQ(gb_face_free_point_names(5, 5).size(), 6u);
  EXPECT_EQ(gb_face_free_point_names(6, 3).size(), 1u);
  // Corner-block aliases: [i, j, k] with j > d-1-k is [i+1, k, d-j].
  EXPECT_TRUE(
      same_interior_point(5, 6, {.side = 0, .j = 4, .layer = 2}, {.side = 1, .j = 2, .layer = 2}));
  EXPECT_FALSE(
      same_interior_point(5, 6, {.side = 0, .j = 3, .layer = 2}, {.side = 1, .j = 2, .layer = 2}));

  const Scene s = asset("gb-interior.json");  // face 0: pentagon, degree 5; face 2: a quad
  EXPECT_TRUE(point_exists(s, PointRef::free_point(0, {.centre = true})));
  EXPECT_TRUE(point_exists(s, PointRef::free_point(0, {.side = 4, .j = 2, .layer = 2})));
  EXPECT_FALSE(point_exists(s, PointRef::free_point(0, {.side = 5, .j = 2, .layer = 2})));
  EXPECT_FALSE(point_exists(s, PointRef::free_point(0, {.side = 1, .j = 1, .layer = 1})));  // G1
  EXPECT_FALSE(point_exists(s, PointRef::free_point(0, {.side = 1, .j = 2, .layer = 3})));
  EXPECT_FALSE(point_exists(s, PointRef::free_point(2, {.centre = true})));  // Gregory quad
  EXPECT_FALSE(point_exists(s, PointRef::free_point(9, {.centre = true})));
  EXPECT_TRUE(point_exists(s, PointRef::free_point(1, {.centre = true})));  // hexagon, degree 3
}

TEST(InteriorPoints, PositionIsDefaultPlusOffsetAndSettingStoresTheDifference) {
  for (const char* file : {"gb-interior.json", "gb-concave-l.json", "default.json"}) {
    SCOPED_TRACE(file);
    Scene s = asset(file);
    const Network& net = *s.network;
    for (int f = 0; f < int(net.faces.size()); ++f) {
      if (!is_gb_face(s, f)) continue;
      const NetworkFace face = net.faces[f];
      const double size = glm::length(net.vertices[face.loop[0]] - net.vertices[face.loop[1]]);
      for (const InteriorOffset& name :
           gb_face_free_point_names(int(face.loop.size()), face.degree)) {
        const PointRef ref = PointRef::free_point(f, name);
        ASSERT_TRUE(point_exists(s, ref)) << describe(ref);
        Vec3 offset(0);
        for (const InteriorOffset& o : face.offsets)
          if (same_interior_point(int(face.loop.size()), face.degree, o, name)) offset = o.by;
        const Vec3 reference = reference_default(s, f, name);
        EXPECT_LT(glm::length(free_point_default(s, ref) - reference), 1e-12 * size)
            << describe(ref);
        EXPECT_LT(glm::length(point_position(s, ref) - (reference + offset)), 1e-12 * size);
      }
      // Setting a position stores position - default; setting the default removes the entry.
      const PointRef centre = PointRef::free_point(f, {.centre = true});
      const Vec3 d = free_point_default(s, centre);
      set_point_position(s, centre, d + Vec3(0.01, -0.02, 0.03));
      const auto& offsets = s.network->faces[f].offsets;
      const auto it = std::find_if(offsets.begin(), offsets.end(),
                                   [](const InteriorOffset& o) { return o.centre; });
      ASSERT_NE(it, offsets.end());
      EXPECT_LT(glm::length(it->by - Vec3(0.01, -0.02, 0.03)), 1e-15);
      EXPECT_LT(glm::length(point_position(s, centre) - (d + Vec3(0.01, -0.02, 0.03))), 1e-15);
      set_point_position(s, centre, d);
      EXPECT_TRUE(std::none_of(s.network->faces[f].offsets.begin(),
                               s.network->faces[f].offsets.end(),
                               [](const InteriorOffset& o) { return o.centre; }));
    }
  }
}

TEST(InteriorPoints, AnAliasNameIsOnePoint) {
  Scene s = asset("gb-interior.json");
  s.network->faces[0].degree = 6;
  s.network->faces[0].offsets = {{.side = 0, .j = 4, .layer = 2, .by = Vec3(0, 0, 0.1)}};
  // [0, 4, 2] is [1, 2, 2]: moving the canonical name replaces the alias's entry.
  const PointRef ref = PointRef::free_point(0, {.side = 1, .j = 2, .layer = 2});
  EXPECT_LT(glm::length(point_position(s, ref) - free_point_default(s, ref) - Vec3(0, 0, 0.1)),
            1e-15);
  set_point_position(s, ref, free_point_default(s, ref) + Vec3(0, 0, 0.2));
  ASSERT_EQ(s.network->faces[0].offsets.size(), 1u);
  EXPECT_EQ(s.network->faces[0].offsets[0].side, 1);
  EXPECT_NEAR(s.network->faces[0].offsets[0].by.z, 0.2, 1e-15);
}

TEST(InteriorCommands, MovingAndDraggingFreePointsUndoBitForBit) {
  Document doc(asset("gb-interior.json"));
  const PointRef centre = PointRef::free_point(1, {.centre = true});  // the hexagon, degree 3
  const Vec3 d = free_point_default(doc.scene(), centre);
  EXPECT_EQ(expect_good_command(doc, std::make_unique<MovePointsCommand>(
                                         std::vector{centre}, std::vector{d + Vec3(0, 0, 0.2)})),
            "move face 1 centre");
  ASSERT_EQ(doc.scene().network->faces[1].offsets.size(), 1u);
  EXPECT_LT(glm::length(doc.scene().network->faces[1].offsets[0].by - Vec3(0, 0, 0.2)), 1e-15);
  // A drag of two free points of the pentagon: one undo step, offsets from the drag's defaults.
  const Scene before = doc.scene();
  const PointRef p = PointRef::free_point(0, {.side = 3, .j = 2, .layer = 2});
  const PointRef c = PointRef::free_point(0, {.centre = true});
  const Vec3 p0 = point_position(doc.scene(), p), c0 = point_position(doc.scene(), c);
  doc.begin_drag({p, c});
  for (int i = 1; i <= 3; ++i) doc.drag_to({p0 + Vec3(0, 0, 0.01 * i), c0 + Vec3(0.01 * i, 0, 0)});
  doc.end_drag();
  EXPECT_LT(glm::length(point_position(doc.scene(), p) - (p0 + Vec3(0, 0, 0.03))), 1e-14);
  EXPECT_LT(glm::length(point_position(doc.scene(), c) - (c0 + Vec3(0.03, 0, 0))), 1e-14);
  EXPECT_EQ(doc.scene().network->faces[0].offsets.size(), 3u);
  EXPECT_EQ(doc.undo_label(), "move 2 points");
  const Scene after = doc.scene();
  doc.undo();
  EXPECT_TRUE(same_bits(doc.scene(), before));
  doc.redo();
  EXPECT_TRUE(same_bits(doc.scene(), after));
  // A drag moving a vertex and a free point of its face: the free point ends where it was put.
  const int v = doc.scene().network->faces[0].loop[2];
  const Vec3 v0 = doc.scene().network->vertices[v];
  doc.begin_drag({PointRef::vertex(v), p});
  const Vec3 p1 = point_position(doc.scene(), p);
  doc.drag_to({v0 + Vec3(0, 0, 0.05), p1 + Vec3(0, 0, 0.05)});
  doc.end_drag();
  EXPECT_LT(glm::length(point_position(doc.scene(), p) - (p1 + Vec3(0, 0, 0.05))), 1e-14);
}

TEST(InteriorCommands, ResetAndRefusals) {
  Document doc(asset("gb-interior.json"));
  EXPECT_EQ(expect_good_command(doc, std::make_unique<ResetInteriorCommand>(0)),
            "reset the interior of face 0");
  EXPECT_TRUE(doc.scene().network->faces[0].offsets.empty());
  EXPECT_EQ(doc.scene().network->faces[0].degree, 5);
  expect_refused(doc, std::make_unique<ResetInteriorCommand>(0), "already at its defaults");
  expect_refused(doc, std::make_unique<ResetInteriorCommand>(2),
                 "Gregory faces have no free interior");
  expect_refused(doc, std::make_unique<SetFaceDegreeCommand>(2, 5),
                 "Gregory faces have no free interior");
  expect_refused(doc, std::make_unique<SetFaceDegreeCommand>(0, 2), "3 to 15");
  expect_refused(doc, std::make_unique<SetFaceDegreeCommand>(0, 16), "3 to 15");
  expect_refused(doc, std::make_unique<SetFaceDegreeCommand>(0, 5), "already has degree 5");
  expect_refused(doc, std::make_unique<SetFaceDegreeCommand>(7, 5), "does not exist");
  Document empty;
  expect_refused(empty, std::make_unique<SetFaceDegreeCommand>(0, 5), "no curve network");
}

TEST(InteriorCommands, DegreeWithoutOffsetsKeepsTheDefaults) {
  Document doc(asset("default.json"));  // face 1: a GB pentagon of degree 3
  EXPECT_EQ(expect_good_command(doc, std::make_unique<SetFaceDegreeCommand>(1, 5)),
            "face 1 degree 5");
  EXPECT_EQ(doc.scene().network->faces[1].degree, 5);
  EXPECT_TRUE(doc.scene().network->faces[1].offsets.empty());
  EXPECT_TRUE(point_exists(doc.scene(), PointRef::free_point(1, {.side = 0, .j = 2, .layer = 2})));
  expect_good_command(doc, std::make_unique<SetFaceDegreeCommand>(1, 3));
  EXPECT_FALSE(point_exists(doc.scene(), PointRef::free_point(1, {.side = 0, .j = 2, .layer = 2})));
}

TEST(InteriorCommands, DegreeChangeRefitsTheOffsets) {
  Document doc(asset("gb-interior.json"));
  const Scene before = doc.scene();
  const NetworkFace& f0 = before.network->faces[0];
  const NetworkTopology topo = validate_network(*before.network, "test");
  std::vector<ProjectedVertex> projected;
  const FaceRibbons ribbons = build_face_ribbons(*before.network, topo, projected)[0];
  const std::vector<InteriorOffset> expected =
      gb_face_offsets_for_degree(ribbons, f0.degree, f0.offsets, 7);
  expect_good_command(doc, std::make_unique<SetFaceDegreeCommand>(0, 7));
  EXPECT_EQ(doc.scene().network->faces[0].degree, 7);
  EXPECT_EQ(doc.scene().network->faces[0].offsets, expected);
  EXPECT_FALSE(expected.empty());
}

TEST(InteriorCommands, AFaceTurnedGregoryDropsItsInterior) {
  Document doc(asset("gb-interior.json"));
  doc.execute(std::make_unique<SetFaceSchemeCommand>(2, FaceScheme::GB));  // a quad
  doc.execute(std::make_unique<SetFaceDegreeCommand>(2, 4));
  const PointRef c = PointRef::free_point(2, {.centre = true});
  doc.execute(std::make_unique<MovePointsCommand>(
      std::vector{c}, std::vector{point_position(doc.scene(), c) + Vec3(0, 0, 0.1)}));
  EXPECT_EQ(expect_good_command(doc, std::make_unique<SetFaceSchemeCommand>(2, FaceScheme::Auto)),
            "face 2 scheme auto (its interior edits dropped)");
  EXPECT_EQ(doc.scene().network->faces[2].degree, 3);
  EXPECT_TRUE(doc.scene().network->faces[2].offsets.empty());
}

TEST(InteriorCommands, ASplitSideResetsTheFacesInterior) {
  Document doc(asset("gb-interior.json"));
  const Network& net = *doc.scene().network;
  // An edge of the pentagon (face 0, degree 5 with two moved points): it becomes a hexagon.
  const auto& loop = net.faces[0].loop;
  int edge = -1;
  for (std::size_t e = 0; e < net.edges.size(); ++e)
    if ((net.edges[e].v[0] == loop[3] && net.edges[e].v[1] == loop[4]) ||
        (net.edges[e].v[0] == loop[4] && net.edges[e].v[1] == loop[3]))
      edge = int(e);
  ASSERT_GE(edge, 0);
  const std::string label = expect_good_command(doc, std::make_unique<SplitEdgeCommand>(edge, 0.5));
  EXPECT_NE(label.find("face 0 now has 6 sides (GB), its interior back at its defaults"),
            std::string::npos)
      << label;
  EXPECT_EQ(doc.scene().network->faces[0].degree, 5);
  EXPECT_TRUE(doc.scene().network->faces[0].offsets.empty());
}

}  // namespace
}  // namespace pl::test
