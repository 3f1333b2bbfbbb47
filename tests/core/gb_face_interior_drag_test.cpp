// The incremental interior drag: changing the offsets of one GB face moves that face's free
// points on its patch as it is (one influence column each), builds no patch, touches no other
// face, and gives the samples a fresh evaluation of the edited scene gives.
#include <gtest/gtest.h>

#include <fstream>
#include <random>
#include <sstream>

#include "core/eval/scene_evaluation.hpp"
#include "core/io/scene_io.hpp"
#include "core/network/face_ribbons.hpp"
#include "core/network/gb_face_interior.hpp"
#include "network_test_util.hpp"

namespace pl {
namespace {

Scene load(const std::string& name) {
  const std::string path = std::string(PATCHLAB_SOURCE_DIR) + "/assets/" + name;
  std::ifstream in(path);
  EXPECT_TRUE(in) << path;
  std::stringstream ss;
  ss << in.rdbuf();
  return parse_scene(ss.str(), path);
}

// Largest difference of positions, first derivatives and unit normals of every sample of every
// surface: positions relative to the network's size, derivatives relative to the largest
// derivative of that surface (a concave face's domain is not the unit n-gon), normals absolute.
double largest_difference(const SceneEvaluation& a, const SceneEvaluation& b, double size) {
  const auto& sa = a.surfaces().surfaces;
  const auto& sb = b.surfaces().surfaces;
  EXPECT_EQ(sa.size(), sb.size());
  double worst = 0;
  for (std::size_t s = 0; s < sa.size() && s < sb.size(); ++s) {
    const PatchEvaluator &ea = *sa[s].evaluator, &eb = *sb[s].evaluator;
    EXPECT_EQ(ea.sample_count(), eb.sample_count());
    const std::size_t count = std::min(ea.sample_count(), eb.sample_count());
    double derivative = 0;
    for (std::size_t i = 0; i < count; ++i)
      derivative =
          std::max({derivative, glm::length(eb.jets()[i].su), glm::length(eb.jets()[i].sv)});
    for (std::size_t i = 0; i < count; ++i) {
      const SurfaceJet &p = ea.jets()[i], &q = eb.jets()[i];
      worst = std::max({worst, glm::length(p.p - q.p) / size, glm::length(p.su - q.su) / derivative,
                        glm::length(p.sv - q.sv) / derivative,
                        glm::length(ea.geometry()[i].normal - eb.geometry()[i].normal)});
    }
  }
  return worst;
}

// Every name of every free point of a face of n sides and degree d (a shared corner-block point
// has two), the centre included.
std::vector<InteriorOffset> free_names(int n, int d) {
  std::vector<InteriorOffset> out{InteriorOffset{.centre = true}};
  for (int i = 0; i < n; ++i)
    for (int k = 2; k < gb_face_layers(d); ++k)
      for (int j = 2; j <= d - 2; ++j) out.push_back({.side = i, .j = j, .layer = k});
  return out;
}

void add_offset(NetworkFace& face, InteriorOffset o) {
  const int n = int(face.loop.size());
  const std::size_t k = interior_point_index(n, face.degree, o);
  for (InteriorOffset& x : face.offsets)
    if (interior_point_index(n, face.degree, x) == k) {
      x.by += o.by;
      return;
    }
  face.offsets.push_back(o);
}

TEST(GBFaceInteriorDrag, OneFreePointMoveIsOneColumnAndEqualsAFreshEvaluation) {
  for (const char* file : {"gb-hole-filling.json", "gb-concave-l.json"}) {
    Scene s = load(file);
    Network& net = *s.network;
    const int face = 0;
    net.faces[face].scheme = FaceScheme::GB;
    net.faces[face].degree = 7;
    const double size = test::network_size(net);
    SceneEvaluation ev(s, 16, std::nullopt);
    const PatchEvaluator* kept = ev.surfaces().surfaces[face].evaluator.get();
    const auto names = free_names(int(net.faces[face].loop.size()), 7);
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-0.05, 0.05);
    double worst = 0;
    for (int step = 0; step < 40; ++step) {
      InteriorOffset o = names[rng() % names.size()];
      o.by = Vec3(u(rng), u(rng), u(rng)) * size;
      add_offset(net.faces[face], o);
      const SyncStats st = ev.sync(s);
      EXPECT_EQ(st.rebuilt_surfaces, 0u);
      EXPECT_EQ(st.moved_points, 1u);  // one free point, one column
      EXPECT_EQ(st.changed_surfaces, std::vector<int>{face});
      EXPECT_EQ(ev.surfaces().surfaces[face].evaluator.get(), kept);
      if (step % 8 == 7) {
        const SceneEvaluation fresh(s, 16, std::nullopt);
        worst = std::max(worst, largest_difference(ev, fresh, size));
      }
    }
    std::printf("%s: 40 incremental free-point moves against fresh evaluations: %.3g\n", file,
                worst);
    EXPECT_LT(worst, 1e-12) << file;
    // Taking every offset away again (still degree 7: the interior form) returns to the default
    // filling, incrementally.
    net.faces[face].offsets.clear();
    const SyncStats st = ev.sync(s);
    EXPECT_EQ(st.rebuilt_surfaces, 0u);
    EXPECT_LT(largest_difference(ev, SceneEvaluation(s, 16, std::nullopt), size), 1e-12);
  }
}

TEST(GBFaceInteriorDrag, ToldWhichFacesChangedItLooksAtThoseAloneAndAgreesWithAFreshEvaluation) {
  Scene s = load("gb-hole-filling.json");
  Network& net = *s.network;
  for (int f : {0, 1}) net.faces[f].scheme = FaceScheme::GB, net.faces[f].degree = 6;
  const double size = test::network_size(net);
  SceneEvaluation told(s, 12, std::nullopt), scanned(s, 12, std::nullopt);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-0.05, 0.05);
  for (int step = 0; step < 30; ++step) {
    const int face = step % 2;
    InteriorOffset o = free_names(int(net.faces[face].loop.size()), 6)[rng() % 5];
    o.by = Vec3(u(rng), u(rng), u(rng)) * size;
    add_offset(net.faces[face], o);
    const InteriorEdit known{{face}};
    const SyncStats a = told.sync(s, &known), b = scanned.sync(s);
    EXPECT_EQ(a.changed_surfaces, b.changed_surfaces);
    EXPECT_EQ(a.moved_points, b.moved_points);
    EXPECT_EQ(a.previous_surface, b.previous_surface);
    EXPECT_FALSE(a.renumbered);
  }
  EXPECT_LT(largest_difference(told, scanned, size), 1e-15);
  EXPECT_LT(largest_difference(told, SceneEvaluation(s, 12, std::nullopt), size), 1e-12);
  // A promise the network does not bear out is noticed: the face's degree changed too, or a
  // listed face that does not exist. Both fall back to comparing everything.
  net.faces[0].degree = 5;
  net.faces[0].offsets.clear();
  const InteriorEdit wrong{{0}};
  const SyncStats st = told.sync(s, &wrong);
  EXPECT_EQ(st.rebuilt_surfaces, 1u);
  const InteriorEdit nowhere{{999}};
  told.sync(s, &nowhere);
  EXPECT_LT(largest_difference(told, SceneEvaluation(s, 12, std::nullopt), size), 1e-12);
}

// What is not only an offset change is a refill: the degree, and the first offset of a plain
// degree-3 face (its patch was not the interior form).
TEST(GBFaceInteriorDrag, DegreeChangesAndFirstOffsetsRefill) {
  Scene s = load("gb-hole-filling.json");
  Network& net = *s.network;
  const double size = test::network_size(net);
  SceneEvaluation ev(s, 12, std::nullopt);
  net.faces[0].offsets.push_back({.centre = true, .by = {0, 0, 0.1}});
  SyncStats st = ev.sync(s);
  EXPECT_EQ(st.changed_surfaces, std::vector<int>{0});
  EXPECT_LT(largest_difference(ev, SceneEvaluation(s, 12, std::nullopt), size), 1e-12);
  net.faces[0].degree = 6;  // the centre offset is still valid
  st = ev.sync(s);
  EXPECT_EQ(st.changed_surfaces, std::vector<int>{0});
  EXPECT_LT(largest_difference(ev, SceneEvaluation(s, 12, std::nullopt), size), 1e-12);
}

// With compact samples (positions and geometry only) an interior edit re-evaluates the face's
// patch as moved, and agrees with a fresh evaluation.
TEST(GBFaceInteriorDrag, CompactStorageFollowsInteriorEdits) {
  Scene s = load("gb-hole-filling.json");
  s.network->faces[0].degree = 6;
  SceneEvaluation ev(s, 12, std::nullopt, "t", SampleStorage::Compact);
  s.network->faces[0].offsets.push_back({.side = 3, .j = 3, .layer = 2, .by = {0, 0.1, 0.2}});
  const SyncStats st = ev.sync(s);
  EXPECT_EQ(st.rebuilt_surfaces, 0u);
  EXPECT_EQ(st.changed_surfaces, std::vector<int>{0});
  const SceneEvaluation fresh(s, 12, std::nullopt, "t", SampleStorage::Compact);
  const PatchEvaluator &a = *ev.surfaces().surfaces[0].evaluator,
                       &b = *fresh.surfaces().surfaces[0].evaluator;
  ASSERT_EQ(a.sample_count(), b.sample_count());
  double worst = 0;
  for (std::size_t i = 0; i < a.sample_count(); ++i)
    worst = std::max({worst, glm::length(a.position(i) - b.position(i)),
                      glm::length(a.geometry()[i].normal - b.geometry()[i].normal)});
  EXPECT_LT(worst, 1e-12);
}

// A vertex move after interior edits, through the engine: the face follows its new patch point
// by point, every free point of the followed patch is its new default plus its offset, and the
// samples are a fresh evaluation's.
TEST(GBFaceInteriorDrag, AVertexMoveAfterInteriorEditsCarriesTheOffsets) {
  Scene s = load("gb-hole-filling.json");
  Network& net = *s.network;
  net.faces[0].degree = 6;
  const double size = test::network_size(net);
  SceneEvaluation ev(s, 12, std::nullopt);
  net.faces[0].offsets = {{.centre = true, .by = {0, 0, 0.2}},
                          {.side = 4, .j = 2, .layer = 2, .by = {0.05, 0, 0.1}}};
  ev.sync(s);
  const int v = net.faces[0].loop[2];
  const Vec3 d(-0.05, 0.08, 0.1);
  net.vertices[v] += d;
  for (NetworkEdge& e : net.edges)
    for (int k = 0; k < 2; ++k)
      if (e.v[k] == v) e.handles[k] += d;
  ev.sync(s);
  const auto& patch =
      dynamic_cast<const GBInteriorPatch&>(ev.surfaces().surfaces[0].evaluator->patch());
  std::vector<ProjectedVertex> projected;
  const auto ribbons = build_face_ribbons(net, ev.filling().topology(), projected);
  const std::vector<Vec3> defaults = gb_face_default_net(ribbons[0], 6);
  double worst = 0;
  for (std::size_t k : patch.free_points()) {
    Vec3 by(0);
    for (const InteriorOffset& o : net.faces[0].offsets)
      if (interior_point_index(5, 6, o) == k) by = o.by;
    worst = std::max(worst, glm::length(patch.control_point(k) - (defaults[k] + by)) / size);
  }
  EXPECT_LT(worst, 1e-12);
  EXPECT_LT(largest_difference(ev, SceneEvaluation(s, 12, std::nullopt), size), 1e-12);
}

}  // namespace
}  // namespace pl
