// The incremental engine (SceneEvaluation over IncrementalFilling) against from-scratch
// evaluations (evaluate_scene: fill_network, new evaluators), and what each kind of edit is
// allowed to touch.
#include "core/eval/scene_evaluation.hpp"

#include <gtest/gtest.h>

#include <random>
#include <set>

#include "core/base/data_error.hpp"
#include "core/patch/bezier_patch.hpp"
#include "network_test_util.hpp"
#include "scene_evaluation_test_util.hpp"

namespace pl {
namespace {

constexpr int kDensity = 12;

Scene scene_of(Network n) {
  Scene s;
  s.network = std::move(n);
  return s;
}

std::set<int> faces_touching(const Network& n, int v) {
  std::set<int> out;
  for (std::size_t f = 0; f < n.faces.size(); ++f)
    for (int w : n.faces[f].loop)
      if (w == v) out.insert(int(f));
  return out;
}

std::vector<uint64_t> revisions(const SceneEvaluation& ev) {
  std::vector<uint64_t> r;
  for (const SceneSurface& s : ev.surfaces().surfaces) r.push_back(s.evaluator->revision());
  return r;
}

std::vector<const PatchEvaluator*> evaluators(const SceneEvaluation& ev) {
  std::vector<const PatchEvaluator*> r;
  for (const SceneSurface& s : ev.surfaces().surfaces) r.push_back(s.evaluator.get());
  return r;
}

double g1_angle(const SceneEvaluation& ev) {
  std::vector<test::FaceSurface> faces;
  for (const SceneSurface& s : ev.surfaces().surfaces)
    if (s.face >= 0) faces.push_back({&s.evaluator->patch(), &s.patch_side});
  return test::max_g1_angle_deg(ev.filling().topology(), faces);
}

void move_vertex(Scene& s, int v, const Vec3& p) {
  Network& n = *s.network;
  const Vec3 d = p - n.vertices[v];
  n.vertices[v] = p;
  for (NetworkEdge& e : n.edges)
    for (int k = 0; k < 2; ++k)
      if (e.v[k] == v) e.handles[k] += d;
}

// Moving a vertex of valence k changes the k faces around it and nothing else, and gives the
// same samples as evaluating everything again.
TEST(SceneEvaluation, MovingAVertexChangesOnlyItsFacesAndEqualsAFreshEvaluation) {
  Scene s = scene_of(test::sphere_blob(true));
  SceneEvaluation ev(s, kDensity, std::nullopt);
  // apex (valence 5), top ring (4), bottom ring vertex 7 = B(1) (3).
  for (auto [v, valence] : {std::pair{0, 5}, {1, 4}, {7, 3}}) {
    ASSERT_EQ(ev.filling().topology().vertex_edges[v].size(), std::size_t(valence));
    const auto rev = revisions(ev);
    const auto kept = evaluators(ev);
    move_vertex(s, v, s.network->vertices[v] + Vec3(0.05, -0.03, 0.04));
    const SyncStats st = ev.sync(s);
    const std::set<int> expected = faces_touching(*s.network, v);
    EXPECT_EQ(expected.size(), std::size_t(valence));
    EXPECT_EQ(std::set<int>(st.changed_surfaces.begin(), st.changed_surfaces.end()), expected)
        << "vertex " << v;
    EXPECT_GT(st.moved_points, 0u);
    EXPECT_EQ(st.rebuilt_surfaces, 0u);
    EXPECT_FALSE(st.renumbered);
    EXPECT_EQ(evaluators(ev), kept);  // every face keeps its evaluator
    const auto rev2 = revisions(ev);
    for (std::size_t f = 0; f < rev.size(); ++f)
      EXPECT_EQ(rev2[f] != rev[f], expected.count(int(f)) == 1) << "vertex " << v << " face " << f;
    test::expect_equals_fresh_evaluation(ev, s, kDensity);
  }
  // The handles moved with their vertices, so every tangent plane survived: still G1.
  EXPECT_LT(g1_angle(ev), 1e-6);
}

TEST(SceneEvaluation, MovingAHandleChangesTheFacesAtItsVertexAndStaysG1InThePlane) {
  Scene s = scene_of(test::sphere_blob(true));
  SceneEvaluation ev(s, kDensity, std::nullopt);
  const int e = 1;  // T(0)-T(1)
  const int v = s.network->edges[e].v[0];
  // Rotate the handle within the vertex's tangent plane (the sphere's), lengthen it.
  const Vec3 p = s.network->vertices[v], h = s.network->edges[e].handles[0];
  const Vec3 d = h - p, n = glm::normalize(p);
  s.network->edges[e].handles[0] = p + 1.3 * (std::cos(0.2) * d + std::sin(0.2) * glm::cross(n, d));
  const SyncStats st = ev.sync(s);
  EXPECT_EQ(std::set<int>(st.changed_surfaces.begin(), st.changed_surfaces.end()),
            faces_touching(*s.network, v));
  test::expect_equals_fresh_evaluation(ev, s, kDensity);
  EXPECT_LT(g1_angle(ev), 1e-6);
  EXPECT_TRUE(ev.surfaces().projected_vertices.empty());
}

TEST(SceneEvaluation, ManyMovesStillEqualAFreshEvaluation) {
  Scene s = scene_of(test::height_field());
  SceneEvaluation ev(s, kDensity, std::nullopt);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> d(-0.05, 0.05);
  std::uniform_int_distribution<int> vertex(0, 8), edge(0, 12), end(0, 1);
  for (int i = 0; i < 40; ++i) {
    if (i % 3 == 0) {
      const int v = vertex(rng);
      move_vertex(s, v, s.network->vertices[v] + Vec3(d(rng), d(rng), d(rng)));
    } else if (i % 3 == 1) {
      const int e = edge(rng), k = end(rng);
      s.network->edges[e].handles[k] += Vec3(d(rng), d(rng), d(rng));
    } else {  // a fixed normal tilted, or given back to the fit
      const int v = vertex(rng);
      auto& normal = s.network->normals[v];
      normal = normal ? std::nullopt : std::optional<Vec3>(glm::normalize(Vec3(d(rng), d(rng), 1)));
    }
    ev.sync(s);
  }
  test::expect_equals_fresh_evaluation(ev, s, kDensity);
  EXPECT_TRUE(ev.sync(s).changed_surfaces.empty());  // nothing changed, nothing moved
}

TEST(SceneEvaluation, ADegenerateMoveThrowsAndLeavesTheEvaluationUnchanged) {
  Scene s = scene_of(test::sphere_blob(true));
  SceneEvaluation ev(s, kDensity, std::nullopt, "blob.json");
  const auto rev = revisions(ev);
  const Scene good = s;
  const int e = 1, v = s.network->edges[e].v[0];
  s.network->edges[e].handles[0] = s.network->vertices[v];
  try {
    ev.sync(s);
    FAIL() << "expected a DataError";
  } catch (const DataError& err) {
    EXPECT_EQ(err.source(), "blob.json");
    EXPECT_EQ(err.where(), "network.edges[1].handles[0]");
  }
  EXPECT_EQ(ev.filling().network(), *good.network);
  EXPECT_EQ(revisions(ev), rev);
  test::expect_equals_fresh_evaluation(ev, good, kDensity);
  // A topology edit that cannot be validated is refused the same way.
  Scene bad = good;
  bad.network->faces[0].loop.push_back(99);
  EXPECT_THROW(ev.sync(bad), DataError);
  EXPECT_EQ(revisions(ev), rev);
  test::expect_equals_fresh_evaluation(ev, good, kDensity);
}

// Deleting a face drops its evaluator and keeps every other face's (renumbered ones included);
// putting it back evaluates only that face.
TEST(SceneEvaluation, TopologyEditsKeepTheEvaluatorsOfUnchangedFaces) {
  Scene s = scene_of(test::sphere_blob(true));
  SceneEvaluation ev(s, kDensity, std::nullopt);
  const auto before = evaluators(ev);
  const NetworkFace removed = s.network->faces[3];
  s.network->faces.erase(s.network->faces.begin() + 3);
  SyncStats st = ev.sync(s);
  EXPECT_TRUE(st.renumbered);
  EXPECT_EQ(st.rebuilt_surfaces, 0u);
  const auto after = evaluators(ev);
  ASSERT_EQ(after.size(), before.size() - 1);
  for (std::size_t f = 0; f < after.size(); ++f)
    EXPECT_EQ(after[f], before[f < 3 ? f : f + 1]) << f;
  std::vector<int> expected;
  for (int f = 3; f < int(after.size()); ++f) expected.push_back(f);  // renumbered
  EXPECT_EQ(st.changed_surfaces, expected);
  test::expect_equals_fresh_evaluation(ev, s, kDensity);
  EXPECT_EQ(ev.surfaces().shared_edges.size(), std::size_t(s.network->edges.size() - 4));

  s.network->faces.push_back(removed);
  st = ev.sync(s);
  EXPECT_EQ(st.rebuilt_surfaces, 1u);
  EXPECT_EQ(st.changed_surfaces, std::vector<int>{int(after.size())});
  test::expect_equals_fresh_evaluation(ev, s, kDensity);

  // New vertices and an edge used by no face change no surface.
  const int a = int(s.network->vertices.size());
  s.network->vertices.push_back(Vec3(3, 0, 0));
  s.network->vertices.push_back(Vec3(4, 0, 0));
  s.network->edges.push_back({{a, a + 1}, {Vec3(3.3, 0, 0.2), Vec3(3.6, 0, 0.2)}, ""});
  st = ev.sync(s);
  EXPECT_TRUE(st.changed_surfaces.empty());
  EXPECT_EQ(st.rebuilt_surfaces, 0u);
  test::expect_equals_fresh_evaluation(ev, s, kDensity);
}

TEST(SceneEvaluation, ExplicitPatchesAreFollowedByIdentity) {
  Scene s = scene_of(test::height_field());
  std::vector<Vec3> pts;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) pts.push_back(Vec3(i, j, 0.1 * i * j) + Vec3(5, 0, 0));
  s.patches.push_back({"b", std::make_shared<BezierPatch>(3, 3, pts)});
  SceneEvaluation ev(s, kDensity, std::nullopt);
  const int surface = int(s.network->faces.size());
  EXPECT_EQ(ev.surfaces().surfaces[surface].name, "b");
  // The same patch object: nothing compared, nothing changed.
  EXPECT_TRUE(ev.sync(s).changed_surfaces.empty());
  // A replaced patch (copy on write) is followed point by point.
  auto copy = std::shared_ptr<Patch>(s.patches[0].patch->clone());
  copy->set_control_point(5, copy->control_point(5) + Vec3(0, 0, 0.3));
  s.patches[0].patch = copy;
  SyncStats st = ev.sync(s);
  EXPECT_EQ(st.changed_surfaces, std::vector<int>{surface});
  EXPECT_EQ(st.moved_points, 1u);
  test::expect_equals_fresh_evaluation(ev, s, kDensity);
  // Without the network, the patch becomes surface 0.
  s.network.reset();
  st = ev.sync(s);
  EXPECT_TRUE(st.renumbered);
  EXPECT_EQ(st.changed_surfaces, std::vector<int>{0});
  EXPECT_EQ(st.rebuilt_surfaces, 0u);
  test::expect_equals_fresh_evaluation(ev, s, kDensity);
}

TEST(SceneEvaluation, SurfacesMayHaveTheirOwnDensity) {
  Scene s = scene_of(test::sphere_blob(true));
  SceneEvaluation ev(s, kDensity, std::nullopt);
  std::vector<int> densities(ev.surfaces().surfaces.size(), kDensity);
  densities[2] = 5;
  const SyncStats st = ev.set_densities(densities);
  EXPECT_EQ(st.changed_surfaces, std::vector<int>{2});
  EXPECT_EQ(ev.surfaces().surfaces[2].evaluator->tessellation().density, 5);
  // A move keeps each surface's density.
  move_vertex(s, s.network->faces[2].loop[0],
              s.network->vertices[s.network->faces[2].loop[0]] + Vec3(0.02, 0.01, 0));
  ev.sync(s);
  EXPECT_EQ(ev.surfaces().surfaces[2].evaluator->tessellation().density, 5);
  TessellationCache cache;
  const SceneSurfaces fresh = evaluate_scene(s, 5, std::nullopt, cache, "fresh");
  test::expect_same_samples(*ev.surfaces().surfaces[2].evaluator, *fresh.surfaces[2].evaluator);
  EXPECT_THROW(ev.set_densities(std::vector<int>{1}), std::invalid_argument);
}

// The compact storage of a view at rest follows moves and topology edits the same way.
TEST(SceneEvaluation, CompactStorageFollowsEditsLikeAFreshEvaluation) {
  Scene s = scene_of(test::sphere_blob(true));
  SceneEvaluation ev(s, kDensity, std::nullopt, "compact", SampleStorage::Compact);
  for (const SceneSurface& surface : ev.surfaces().surfaces)
    EXPECT_TRUE(surface.evaluator->jets().empty());
  move_vertex(s, 1, s.network->vertices[1] + Vec3(0.03, 0.02, -0.01));
  s.network->edges[5].handles[0] += Vec3(0, 0.01, 0.01);
  ev.sync(s);
  test::expect_equals_fresh_evaluation(ev, s, kDensity);
  s.network->faces.erase(s.network->faces.begin() + 4);
  ev.sync(s);
  test::expect_equals_fresh_evaluation(ev, s, kDensity);
}

}  // namespace
}  // namespace pl
