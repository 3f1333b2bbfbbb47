// The Add Vertex tool on a vertex that is already there: the hover names that vertex, and a click
// takes it (selected, the status bar says so) instead of putting a near-duplicate a hair beside
// it, which would look like one vertex and split the network in two at that place.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "model_driver.hpp"

namespace pl::test {

TEST(AddVertex, AClickOnAVertexSelectsItInsteadOfAddingAnother) {
  ModelDriver d(1280, 720);
  EditorModel& m = d.model();
  d.new_scene();
  d.key("V");
  d.click(d.world_to_pixel(Vec3(0.2, 0.1, 0)));
  d.click(d.world_to_pixel(Vec3(-0.4, 0.3, 0)));
  ASSERT_EQ(m.doc().scene().network->vertices.size(), 2u);
  ASSERT_EQ(m.selection().points(), std::vector<PointRef>{PointRef::vertex(1)});
  const std::vector<Vec3> before = m.doc().scene().network->vertices;
  const uint64_t revision = m.doc().revision();

  // On the vertex, and a couple of pixels beside its centre, as a hand lands.
  for (const Vec2& off : {Vec2(0, 0), Vec2(2, -1)}) {
    d.move(d.vertex(0) + off);
    ASSERT_TRUE(m.mouse().under.item) << "the hover names the vertex";
    ASSERT_EQ(*m.mouse().under.item, SelectionItem::of_point(PointRef::vertex(0)));
    d.click(d.vertex(0) + off);
    EXPECT_EQ(m.doc().scene().network->vertices, before) << "no vertex added or moved";
    EXPECT_EQ(m.doc().revision(), revision) << "no undo step";
    EXPECT_EQ(m.selection().points(), std::vector<PointRef>{PointRef::vertex(0)});
    EXPECT_NE(m.status().message().find("vertex 0"), std::string::npos) << m.status().message();
    d.key("Esc");  // back to Select, then the selection cleared
    d.key("Esc");
    d.key("V");
  }

  // Away from the vertices the tool adds one as before.
  d.click(d.world_to_pixel(Vec3(0.6, -0.5, 0)));
  EXPECT_EQ(m.doc().scene().network->vertices.size(), 3u);
}

}  // namespace pl::test
