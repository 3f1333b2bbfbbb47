// Scene entries of the classic types: every sample scene in assets/classic reads, evaluates
// without non-finite samples, and round-trips; bad data is a DataError naming file and path.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "core/base/data_error.hpp"
#include "core/domain/tessellation_cache.hpp"
#include "core/eval/scene_surfaces.hpp"
#include "core/io/scene_io.hpp"
#include "test_util.hpp"

namespace pl {
namespace {

TEST(ClassicScenes, SampleScenesReadEvaluateAndRoundTrip) {
  const std::filesystem::path dir = std::filesystem::path(PATCHLAB_SOURCE_DIR) / "assets/classic";
  int files = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    if (e.path().extension() != ".json") continue;
    ++files;
    const Scene a = read_scene(e.path());
    ASSERT_FALSE(a.patches.empty()) << e.path();
    const Scene b = parse_scene(scene_to_json(a), "round trip");
    ASSERT_EQ(a.patches.size(), b.patches.size());
    for (std::size_t i = 0; i < a.patches.size(); ++i) {
      EXPECT_EQ(a.patches[i].patch->type(), b.patches[i].patch->type());
      EXPECT_EQ(a.patches[i].patch->control_points(), b.patches[i].patch->control_points());
      for (double u : {0.1, 0.5, 0.77})
        EXPECT_EQ(a.patches[i].patch->evaluate({u, 0.3}).p,
                  b.patches[i].patch->evaluate({u, 0.3}).p);
    }
    TessellationCache cache;
    const SceneSurfaces ss = evaluate_scene(a, 24, std::nullopt, cache, e.path().string());
    for (const SceneSurface& s : ss.surfaces)
      for (std::size_t k = 0; k < s.evaluator->sample_count(); ++k) {
        const auto& g = s.evaluator->geometry()[k];
        ASSERT_TRUE(std::isfinite(g.gaussian) && std::isfinite(g.mean) && std::isfinite(g.normal.x))
            << e.path() << " " << s.name << " sample " << k;
      }
  }
  EXPECT_GE(files, 8);
}

void expect_data_error(const std::string& patch_json, const std::string& where_part) {
  const std::string text = R"({"patchlab": 1, "patches": [)" + patch_json + "]}";
  try {
    parse_scene(text, "bad.json");
    ADD_FAILURE() << "accepted: " << patch_json;
  } catch (const DataError& e) {
    EXPECT_EQ(e.source(), "bad.json");
    EXPECT_NE(std::string(e.what()).find(where_part), std::string::npos) << e.what();
  }
}

TEST(ClassicScenes, BadDataNamesFileAndPlace) {
  expect_data_error(R"({"type": "interpolating", "points": [[0,0,0]]})", "patches[0].points");
  expect_data_error(R"({"type": "hermite", "q": []})", "patches[0].q");
  expect_data_error(R"({"type": "bspline", "degree": [3, 3], "size": [4, 4],
      "knots_u": [0,0,0,0,1,1,1], "points": []})",
                    "patches[0].knots_u");
  expect_data_error(R"({"type": "bspline", "degree": [1, 1], "size": [2, 2],
      "knots_u": [0,0,1,1], "knots_v": [0,0,1,0.5], "points": [[0,0,0],[0,0,0],[0,0,0],[0,0,0]]})",
                    "patches[0].knots_v");
  expect_data_error(R"({"type": "nurbs", "degree": [1, 1], "size": [2, 2],
      "points": [[0,0,0],[1,0,0],[0,1,0],[1,1,0]], "weights": [1, 1, 0, 1]})",
                    "patches[0].weights[2]");
  expect_data_error(R"({"type": "coons-network", "size": [2, 2], "s": [[0, 1], [0, 0]],
      "t": [[0, 1], [0, 1]], "data": []})",
                    "patches[0].s[1]");
  std::string zeros = "[0,0,0]";
  for (int k = 1; k < 16; ++k) zeros += ",[0,0,0]";
  expect_data_error(R"({"type": "coons-network", "size": [2, 2], "s": [[0, 1], [0, 1]],
      "t": [[0, 1], [0, 1]], "data": [)" +
                        zeros + R"(], "lengths": "odd"})",
                    "patches[0].lengths");
  expect_data_error(
      R"({"type": "pair-join", "order": 1, "aux_degree": [3, 1], "aux": [[0,0,0],[0,1,0],
      [1,0,0],[1,1,0],[2,0,0],[2,1,0],[3,0,0],[3,1,0]], "a": {"b1": [0], "c1": [1]}, "b": {"b1": [0], "c1": []}})",
      "patches[0].b.c1");
  expect_data_error(
      R"({"type": "gap-fill", "q": {"degree": [3, 3], "size": [4, 4], "points": []}, "r": {}})",
      "patches[0].q.points");
  expect_data_error(
      R"({"type": "catmull-clark", "vertices": [[0,0,0],[1,0,0],[1,1,0]], "faces": [[0,1,2,3]]})",
      "patches[0].faces[0][3]");
  expect_data_error(R"({"type": "catmull-clark", "vertices": [[0,0,0],[1,0,0],[1,1,0],[0,1,0]],
      "faces": [[0,1,2,3],[0,1,2,3]]})",
                    "patches[0].faces");
  expect_data_error(R"({"type": "bspline", "degree": [99, 1], "size": [2, 2], "points": []})",
                    "patches[0].degree[0]");
}

}  // namespace
}  // namespace pl
