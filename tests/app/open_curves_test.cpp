// Curves made elsewhere open as a scene of free curves: OBJ polylines (and STEP/IGES edges, read
// by the CAD library's reader), untitled so that Save asks where (the file they came from is never
// overwritten), and then turned into network edges and a face like drawn curves.
#include <gtest/gtest.h>

#include <algorithm>

#include "app/document/curves_to_edges_command.hpp"
#include "app/document/network_commands.hpp"
#include "app/document/scene_file.hpp"
#include "app/editor/logic/document_session.hpp"
#include "cli_test_util.hpp"
#include "core/base/data_error.hpp"

namespace pl::test {
namespace {

TEST(OpenCurves, AnObjOfPolylinesOpensUntitledAndBecomesAFace) {
  TempDir dir;
  const auto obj = dir.file("outline.obj",
                            "v 0 0 0\nv 2 0 0.2\nv 2 2 0\nv 0 2 0.2\n"
                            "l 1 2\nl 2 3\nl 3 4\nl 4 1\n");
  const Scene scene = load_scene_file(obj);
  ASSERT_EQ(scene.curves.size(), 4u);
  EXPECT_FALSE(scene.network);
  DocumentSession session;
  session.open(obj);
  EXPECT_TRUE(session.untitled()) << "Save must not write OBJ over the file it came from";
  EXPECT_NE(session.title().find("outline.obj"), std::string::npos) << session.title();
  Document& doc = session.doc();
  doc.execute(std::make_unique<CurvesToEdgesCommand>(std::vector{0, 1, 2, 3}));
  EXPECT_EQ(doc.scene().network->vertices.size(), 4u);
  doc.execute(MakeFaceCommand::from_edges({0, 1, 2, 3}));
  EXPECT_EQ(doc.scene().network->faces.size(), 1u);
  const auto saved = session.save_as(dir / "outline");
  EXPECT_EQ(saved.extension(), ".json");
}

TEST(OpenCurves, TheOpenListNamesEveryReadableType) {
  const auto& e = openable_extensions();
  for (const char* x : {".json", ".gbp", ".obj", ".step", ".stp", ".igs", ".iges"})
    EXPECT_NE(std::find(e.begin(), e.end(), x), e.end()) << x;
  TempDir dir;
  EXPECT_THROW(load_scene_file(dir.file("a.txt", "hello")), DataError);
}

}  // namespace
}  // namespace pl::test
