// The authoring scenario of the editor's end-to-end test (tests/app/editor_authoring_e2e.py),
// step for step, on the editor model with synthetic events and no window: from File > New in
// an orthographic view, ten vertices clicked onto the work plane, a pentagon's edges as a chain,
// the pentagon made on its edges and a quad, a triangle and a quad on their vertices, vertex 0's
// tangent plane turned by its knob, an edge split where it is clicked, the triangle deleted and
// made again, a quad set to GB from the right-click menu, saved through Save As. The saved file
// must be the one the real editor saves, byte for byte (tests/data/editor/authoring_scenario.json,
// which the end-to-end test checks its own file against); then undo to the empty scene and redo
// to the end save the same bytes again.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "model_driver.hpp"

namespace pl::test {

namespace {

namespace fs = std::filesystem;

std::string read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

struct Counts {
  std::size_t vertices = 0, edges = 0, faces = 0;
};

Counts counts(EditorModel& m) {
  const auto& net = m.doc().scene().network;
  if (!net) return {};
  return {net->vertices.size(), net->edges.size(), net->faces.size()};
}

// The network on the XY plane: a pentagon (0-4), a quad below it (0, 6, 5, 1), a triangle on
// its right (1, 7, 2) and a quad on its left (0, 4, 8, 9); scaled by 0.75.
const double kPoints[10][2] = {{0, 0},  {1, 0},  {1.3, 0.9}, {0.5, 1.5},  {-0.3, 0.9},
                               {1, -1}, {0, -1}, {2.1, 0.3}, {-1.1, 1.0}, {-1.0, -0.1}};
constexpr double kScale = 0.75;

}  // namespace

TEST(AuthoringScenario, EndsAtTheEndToEndTestsFileByteForByte) {
  ModelDriver d(1200, 760);
  EditorModel& m = d.model();
  TempDir dir("authoring");
  const fs::path saved = dir.path() / "built.json";

  // File > New, then the orthographic view, where window pixels map to the work plane affinely.
  d.key("Ctrl+N");
  ASSERT_EQ(counts(m).vertices, 0u);
  ASSERT_FALSE(m.doc().can_undo());
  d.key("5");
  ASSERT_TRUE(m.nav().camera().orthographic);

  // Vertices: clicks on the work plane.
  d.key("V");
  ASSERT_EQ(m.tools().active().name(), "Add Vertex");
  for (int i = 0; i < 10; ++i) {
    const Vec2 px = d.world_to_pixel(Vec3(kScale * kPoints[i][0], kScale * kPoints[i][1], 0));
    ASSERT_TRUE(60 < px.x && px.x < 840 && 40 < px.y && px.y < 720) << "vertex " << i;
    d.click(px);
    ASSERT_EQ(counts(m).vertices, std::size_t(i + 1)) << "vertex " << i;
  }

  // The pentagon's edges: a chain of clicks with the Add Edge tool, back to vertex 0.
  d.key("E");
  ASSERT_EQ(m.tools().active().name(), "Add Edge");
  const int chain[] = {0, 1, 2, 3, 4, 0};
  for (int n = 0; n < 6; ++n) {
    d.click(d.vertex(chain[n]));
    ASSERT_EQ(counts(m).edges, std::size_t(n)) << "edge " << n - 1;
  }
  d.click(d.vertex(0));  // the chain's vertex again: the chain ends
  EXPECT_EQ(m.status().message().rfind("edge chain ended", 0), 0u) << m.status().message();

  // Faces: the pentagon on its edges, the others on their vertices.
  d.key("M");
  for (int e = 0; e < 5; ++e) {
    d.click(d.edge(e));
    EXPECT_EQ(m.status().message().rfind("face on " + std::to_string(e + 1) + " edges", 0), 0u)
        << m.status().message();
  }
  d.key("Enter");
  ASSERT_EQ(counts(m).faces, 1u);
  const std::vector<std::vector<int>> loops = {{0, 6, 5, 1}, {1, 7, 2}, {0, 4, 8, 9}};
  for (std::size_t f = 0; f < loops.size(); ++f) {
    for (int v : loops[f]) d.click(d.vertex(v));
    if (f == 1)
      d.key("Enter");
    else
      d.click(d.vertex(loops[f][0]));  // the first vertex again closes the chain
    ASSERT_EQ(counts(m).faces, f + 2) << "face " << f + 1;
  }
  ASSERT_EQ(counts(m).vertices, 10u);
  ASSERT_EQ(counts(m).edges, 13u);

  // Turn vertex 0's tangent plane by its normal's knob.
  d.key("Q");
  d.click(d.vertex(0));
  const Vec2 knob = d.knob(0);
  const uint64_t before = m.doc().revision();
  d.press(knob);
  for (double s : {8.0, 16.0, 24.0, 32.0}) d.drag_to(knob + Vec2(s, s / 4));
  d.release();
  ASSERT_GT(m.doc().revision(), before);
  EXPECT_GT(std::abs(d.knob(0).x - knob.x), 10);
  EXPECT_EQ(m.status().message().rfind("fix the tangent plane of vertex 0", 0), 0u)
      << m.status().message();

  // Split the left quad's outer edge (8 -> 9, made with that face) where it is clicked.
  d.key("K");
  const int split_edge = 11;  // a face made on vertices adds its missing edges in loop order
  d.move(d.edge(split_edge));
  d.click(d.edge(split_edge));
  EXPECT_NE(m.status().message().find("now has 5 sides (GB)"), std::string::npos)
      << m.status().message();
  ASSERT_EQ(counts(m).vertices, 11u);

  // Delete the triangle (face 2) and make it again.
  d.key("Q");
  d.click(d.face(2));
  ASSERT_EQ(m.selection().items(), std::vector<SelectionItem>{SelectionItem::face(2)});
  d.key("Del");
  ASSERT_EQ(counts(m).faces, 3u);
  d.key("M");
  for (int v : {1, 7, 2}) d.click(d.vertex(v));
  d.key("Enter");
  ASSERT_EQ(counts(m).faces, 4u);

  // The first quad (face 1) to GB from the right-click menu.
  d.key("Q");
  d.click(d.face(1), 1);
  ASSERT_EQ(m.context_target(), ContextTarget::Face);
  const Action* gb = m.actions().find("face.scheme.gb");
  ASSERT_NE(gb, nullptr);
  ASSERT_TRUE(gb->context & context_bit(ContextTarget::Face)) << "GB is not in a face's menu";
  ASSERT_TRUE(m.actions().run("face.scheme.gb"));
  m.close_context();
  d.settle();
  EXPECT_EQ(m.status().message().rfind("face 1 scheme gb", 0), 0u) << m.status().message();

  // Save: untitled, so the shell is asked for a name; the dialog's answer is the path.
  d.key("Ctrl+S");
  ASSERT_EQ(d.shell().save_as_requests, 1);
  m.save_as(saved);
  d.settle();
  ASSERT_EQ(d.shell().errors, 0) << d.shell().last_error;
  const std::string first = read_file(saved);
  const fs::path reference =
      fs::path(PATCHLAB_TEST_DATA_DIR) / "editor" / "authoring_scenario.json";
  EXPECT_EQ(first, read_file(reference))
      << "the model saved another file than the editor driven by the end-to-end test";

  // Undo back to the empty scene, redo to the end, save again: the same bytes.
  while (m.doc().can_undo()) d.key("Ctrl+Z");
  EXPECT_EQ(counts(m).vertices, 0u);
  EXPECT_EQ(counts(m).faces, 0u);
  while (m.doc().can_redo()) d.key("Ctrl+Y");
  EXPECT_EQ(counts(m).vertices, 11u);
  EXPECT_EQ(counts(m).faces, 4u);
  d.key("Ctrl+S");
  EXPECT_EQ(d.shell().save_as_requests, 1) << "a titled document is saved in place";
  EXPECT_EQ(read_file(saved), first);
}

}  // namespace pl::test
