// The incremental engine and the ribbon schemes: a face switched from one ribbon scheme to
// another, or given another fullness, keeps its patch type, control points and domain but not its
// basis; the live evaluation must end on a fresh evaluation's samples.
#include <gtest/gtest.h>

#include "core/analysis/compared_schemes.hpp"
#include "core/io/scene_io.hpp"
#include "core/scene/network_edit.hpp"
#include "scene_evaluation_test_util.hpp"

namespace pl {
namespace {

TEST(RibbonSchemeSwitch, EverySchemeChangeAndFullnessChangeEndsOnTheFreshSamples) {
  Scene scene = read_scene(PATCHLAB_SOURCE_DIR "/assets/gb-hole-filling.json");
  SceneEvaluation live(scene, 8, std::nullopt, "live");
  Network& net = *scene.network;
  const int face = 0;  // the pentagon
  for (FaceScheme s : comparable_schemes()) {
    if (s == FaceScheme::Gregory) continue;  // five sides
    set_face_scheme(net, face, s);
    live.sync(scene);
    SCOPED_TRACE(scheme_keyword(s));
    test::expect_equals_fresh_evaluation(live, scene, 8);
  }
  set_face_scheme(net, face, *comparable_scheme("midpoint"));
  live.sync(scene);
  for (double fullness : {0.5, 1.5}) {
    net.faces[face].fullness = fullness;
    live.sync(scene);
    SCOPED_TRACE(fullness);
    test::expect_equals_fresh_evaluation(live, scene, 8);
  }
}

}  // namespace
}  // namespace pl
