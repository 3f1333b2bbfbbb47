#include "core/io/scene_io.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/base/data_error.hpp"
#include "core/io/atomic_file.hpp"
#include "core/patch/bezier_patch.hpp"
#include "test_util.hpp"

namespace pl {
namespace {

const char* kSpecExample = R"({
  "patchlab": 1,
  "name": "two quads",
  "network": {
    "vertices": [[0,0,0],[1,0,0],[2,0,0],[0,1,0],[1,1,0.3],[2,1,0]],
    "edges": [
      {"v": [0,1], "handles": [[0.33,0,0],[0.67,0,0]]},
      {"v": [1,2], "handles": [[1.33,0,0],[1.67,0,0]]},
      {"v": [3,4], "handles": [[0.33,1,0.1],[0.67,1,0.3]]},
      {"v": [4,5], "handles": [[1.33,1,0.3],[1.67,1,0.1]]},
      {"v": [0,3], "handles": [[0,0.33,0],[0,0.67,0]]},
      {"v": [1,4], "handles": [[1,0.33,0.1],[1,0.67,0.3]]},
      {"v": [2,5], "handles": [[2,0.33,0],[2,0.67,0]]}
    ],
    "faces": [{"loop": [0,1,4,3]}, {"loop": [1,2,5,4], "scheme": "gb"}]
  }
})";

TEST(SceneIo, SpecExampleReadsAndValidates) {
  const Scene s = parse_scene(kSpecExample, "example.json");
  ASSERT_TRUE(s.network);
  EXPECT_EQ(s.name, "two quads");
  EXPECT_EQ(s.network->faces.size(), 2u);
  EXPECT_EQ(s.network->faces[1].scheme, FaceScheme::GB);
  const NetworkTopology t = validate_network(*s.network, "example.json");
  // Edge 5 (1-4) is shared: face 0 runs 1->4 (forward), face 1 runs 4->1 (reversed).
  ASSERT_EQ(t.edge_faces[5].size(), 2u);
  EXPECT_FALSE(t.face_sides[0][1].reversed);
  EXPECT_TRUE(t.face_sides[1][2].reversed);
}

TEST(SceneIo, RoundTripKeepsEveryDoubleBitForBit) {
  Scene s = parse_scene(kSpecExample, "example.json");
  s.patches.push_back({"odd numbers", std::make_shared<BezierPatch>(
                                          1, 1,
                                          std::vector<Vec3>{{0.1, 1.0 / 3, 2e-300},
                                                            {M_PI, -0.0, 3.7e153},
                                                            {5e-324, 7, 8},
                                                            {0.30000000000000004, 1, 1}})});
  s.view_json = R"({"camera":{"distance":3.5}})";
  const std::string once = scene_to_json(s);
  const Scene back = parse_scene(once, "again.json");
  EXPECT_EQ(scene_to_json(back), once);
  const auto& p = back.patches[0].patch->control_points();
  EXPECT_EQ(p[0].y, 1.0 / 3);
  EXPECT_EQ(p[1].x, M_PI);
  EXPECT_EQ(p[2].x, 5e-324);
  EXPECT_EQ(p[3].x, 0.30000000000000004);
  EXPECT_EQ(back.network->vertices[4].z, 0.3);
  EXPECT_EQ(back.view_json, s.view_json);
}

TEST(SceneIo, EmptySceneIsValid) {
  const Scene s = parse_scene(R"({"patchlab": 1})", "e.json");
  EXPECT_FALSE(s.network);
  EXPECT_TRUE(s.patches.empty());
}

TEST(SceneIo, AtomicSaveLeavesOldFileWhenWritingFails) {
  const auto dir = std::filesystem::temp_directory_path() / "patchlab-atomic-test";
  std::filesystem::create_directories(dir);
  const auto target = dir / "scene.json";
  write_file_atomically(target, "old\n");
  // The target's directory becomes read-only: the temporary file cannot be created.
  std::filesystem::permissions(
      dir, std::filesystem::perms::owner_read | std::filesystem::perms::owner_exec);
  bool threw = false;
  try {
    write_file_atomically(target, "new\n");
  } catch (const DataError&) {
    threw = true;
  }
  std::filesystem::permissions(dir, std::filesystem::perms::owner_all);
  // Root ignores directory permissions; then the write succeeds, which is also atomic.
  if (threw)
    EXPECT_EQ(read_text_file(target), "old\n");
  else
    EXPECT_EQ(read_text_file(target), "new\n");
  // No temporary files are left behind either way.
  int files = 0;
  for (auto& e : std::filesystem::directory_iterator(dir)) files += e.is_regular_file();
  EXPECT_EQ(files, 1);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace pl
