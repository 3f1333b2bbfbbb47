// Authoring through the document against the geometry it must keep: random constrained handle
// drags keep every shared edge G1 (measured from exact derivatives of a from-scratch filling),
// and the live engine followed through random moves and topology edits equals a from-scratch
// evaluation.
#include <gtest/gtest.h>

#include <random>

#include "app/document/document.hpp"
#include "app/document/network_commands.hpp"
#include "cli_test_util.hpp"
#include "core/base/data_error.hpp"
#include "core/io/scene_io.hpp"
#include "core/network/network_filling.hpp"
#include "core/network/sample_networks.hpp"
#include "core/network_test_util.hpp"
#include "core/scene_evaluation_test_util.hpp"

namespace pl::test {
namespace {

std::vector<std::pair<std::string, Scene>> sample_scenes() {
  std::vector<std::pair<std::string, Scene>> out;
  for (const char* name : {"default.json", "gb-concave-l.json", "gb-hole-filling.json",
                           "gregory-blob-closed.json", "gregory-cap-open.json"})
    out.emplace_back(name,
                     read_scene(std::filesystem::path(PATCHLAB_SOURCE_DIR) / "assets" / name));
  Scene sphere;
  sphere.network = cube_sphere_network(3);
  out.emplace_back("cube sphere 3x3", std::move(sphere));
  return out;
}

// 200 drags of random handles, each three steps to random targets in 3D up to a quarter of the
// handle's length from where the file has it (so the drags do not random-walk a sharp corner
// into a folded face, which no filling could make G1): the default drag keeps every handle in
// its vertex's plane, so nothing is projected and every shared edge stays G1.
TEST(AuthoringEngine, TwoHundredRandomHandleDragsKeepTheSampleNetworksG1) {
  for (auto& [name, scene] : sample_scenes()) {
    ASSERT_TRUE(scene.network) << name;
    const Continuity start = filled_continuity(*scene.network);
    ASSERT_LT(start.angle_deg, 1e-6) << name;
    ASSERT_EQ(start.projected, 0u) << name;
    Document doc(scene);
    std::mt19937 rng(17);
    std::uniform_int_distribution<int> edge(0, int(scene.network->edges.size()) - 1), end(0, 1);
    std::normal_distribution<double> gauss;
    for (int drag = 0; drag < 200; ++drag) {
      const int e = edge(rng), k = end(rng);
      const Network& n = *scene.network;
      const Vec3 h = n.edges[e].handles[k], v = n.vertices[n.edges[e].v[k]];
      const double reach = glm::length(h - v) / 4;
      doc.begin_drag({PointRef::handle(e, k)});
      for (int step = 0; step < 3; ++step)
        doc.drag_to({h + reach * glm::normalize(Vec3(gauss(rng), gauss(rng), gauss(rng)))});
      doc.end_drag();
    }
    const Continuity after = filled_continuity(*doc.scene().network);
    EXPECT_LT(after.angle_deg, 1e-6) << name;
    EXPECT_EQ(after.projected, 0u) << name;
    EXPECT_NE(*doc.scene().network, *scene.network) << name;  // the drags did move handles
    std::printf("figure random_drags_max_g1_deg %s %.3g deg\n", name.c_str(), after.angle_deg);
  }
}

// A random mix of edits, each followed by a sync of a live evaluation that is never rebuilt:
// vertex and handle drags (kept in the plane and free), typed moves, normals, schemes, splits,
// deletions, new faces, hole filling, undo and redo. After every step the live evaluation
// equals a from-scratch one to 1e-12.
TEST(AuthoringEngine, TheLiveEngineEqualsAFreshEvaluationAfterRandomEdits) {
  Scene s;
  s.network = sphere_blob(false);
  Document doc(s);
  constexpr int kDensity = 7;
  SceneEvaluation live(doc.scene(), kDensity, std::nullopt, "live");
  std::mt19937 rng(3);
  std::normal_distribution<double> gauss;
  const auto pick = [&](std::size_t count) {
    return std::uniform_int_distribution<int>(0, int(count) - 1)(rng);
  };
  const auto small = [&](double size) { return size * Vec3(gauss(rng), gauss(rng), gauss(rng)); };
  int refused = 0, topology = 0, unfillable = 0;
  const auto follow = [&] {  // a drag step; whether it can be filled is checked after the edit
    try {
      live.sync(doc.scene());
    } catch (const DataError&) {
    }
  };
  for (int step = 0; step < 120; ++step) {
    const Network& n = *doc.scene().network;
    try {
      switch (pick(12)) {
        case 0:
        case 1: {  // a vertex drag
          const int v = pick(n.vertices.size());
          doc.begin_drag({PointRef::vertex(v)});
          for (int i = 0; i < 3; ++i) {
            doc.drag_to({n.vertices[v] + small(0.02)});
            follow();
          }
          doc.end_drag();
          break;
        }
        case 2:
        case 3: {  // a handle drag, in the plane or turning it
          const int e = pick(n.edges.size()), k = pick(2);
          doc.begin_drag({PointRef::handle(e, k)},
                         step % 2 ? HandleMode::KeepPlane : HandleMode::RotatePlane);
          for (int i = 0; i < 3; ++i) {
            doc.drag_to({n.edges[e].handles[k] + small(0.02)});
            follow();
          }
          doc.end_drag();
          break;
        }
        case 4: {  // a typed coordinate
          const int v = pick(n.vertices.size());
          doc.execute(std::make_unique<MovePointsCommand>(
              std::vector{PointRef::vertex(v)}, std::vector{n.vertices[v] + small(0.02)}));
          break;
        }
        case 5: {  // a vertex plane turned, or fitted again
          const int v = pick(n.vertices.size());
          doc.execute(std::make_unique<SetVertexNormalCommand>(
              v, step % 3 ? std::optional<Vec3>(glm::normalize(n.vertices[v]) + small(0.05))
                          : std::nullopt));
          break;
        }
        case 6:
          doc.execute(std::make_unique<SetFaceSchemeCommand>(
              pick(n.faces.size()), step % 2 ? FaceScheme::GB : FaceScheme::Auto));
          break;
        case 7:
          doc.execute(
              std::make_unique<SplitEdgeCommand>(pick(n.edges.size()), 0.3 + 0.4 * (step % 2)));
          ++topology;
          break;
        case 8:
          doc.execute(delete_face_command(pick(n.faces.size())));
          ++topology;
          break;
        case 9:
          doc.execute(std::make_unique<FillHolesCommand>());
          ++topology;
          break;
        case 10:
          doc.undo();
          break;
        case 11:
          doc.redo();
          break;
      }
    } catch (const EditRefused&) {
      ++refused;  // refused edits change nothing; the evaluation must still match
    }
    try {
      live.sync(doc.scene());
    } catch (const DataError& e) {
      // A drag can leave what cannot be filled (the editor shows why and keeps the last
      // surfaces): a fresh evaluation must refuse it too, and the live one must still hold
      // the last scene it followed.
      TessellationCache cache;
      EXPECT_THROW(evaluate_scene(doc.scene(), kDensity, std::nullopt, cache, "fresh"), DataError);
      ++unfillable;
      continue;
    }
    expect_equals_fresh_evaluation(live, doc.scene(), kDensity);
    if (::testing::Test::HasFailure()) {
      ADD_FAILURE() << "at step " << step;
      return;
    }
  }
  EXPECT_GT(topology, 10);
  std::printf("figure random_edits_refused %d of 120, unfillable %d\n", refused, unfillable);
}

}  // namespace
}  // namespace pl::test
