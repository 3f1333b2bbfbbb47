// Move, rotate and scale of a selection: the selected vertices move as one rigid piece with their
// handles and fixed normals, everything else stays bit for bit, and the filled network stays G1
// on every shared edge with no projected vertex (measured on a from-scratch filling with exact
// derivatives, not on the editor's samples). Rotating a whole scene rotates its surfaces.
#include "app/document/transform_command.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <random>

#include "command_test_util.hpp"
#include "core/eval/scene_surfaces.hpp"
#include "core/network_test_util.hpp"

namespace pl::test {
namespace {

Scene scene_of(Network n) {
  Scene s;
  s.network = std::move(n);
  return s;
}

// The test networks: an open height field (fixed normals at every other vertex, a valence-5
// vertex, two GB faces) and a closed ellipsoid blob (fitted planes, valences 3 to 5).
std::vector<Scene> test_scenes() {
  Network field = height_field();
  for (auto& n : field.normals)
    if (n) n = stored_normal(*n);  // as a file stores them: the round trip keeps them bit for bit
  field.faces[0].scheme = FaceScheme::GB;
  field.faces[3].scheme = FaceScheme::GB;
  const glm::dmat3 stretch(Vec3(1.3, 0.1, 0), Vec3(0, 0.8, 0.2), Vec3(0.1, 0, 1.1));
  return {scene_of(field), scene_of(mapped(sphere_blob(true), stretch))};
}

Vec3 random_unit(std::mt19937& rng) {
  std::normal_distribution<double> g;
  return glm::normalize(Vec3(g(rng), g(rng), g(rng)));
}

enum class Kind { Rotate, Scale, Move };

// What a designer selects and transforms: one vertex about itself (which turns its tangent
// plane), the vertices of one face about their centre, or the whole network about any point.
enum class Part { Vertex, Face, Everything };

// A random similarity of `kind` for `part`, whose vertices have centre `centre` and the network
// size `size`: any angle, factor and offset for the whole network (a rigid motion); for a part,
// within what keeps the faces unfolded (a quarter turn of one vertex's plane, a twelfth of a turn
// of a face, a face scaled by 0.7 to 1.4 or moved by a tenth of the size).
Similarity random_similarity(Kind kind, Part part, const Vec3& centre, double size,
                             std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1, 1);
  const bool all = part == Part::Everything;
  const Vec3 pivot = all ? centre + size * Vec3(u(rng), u(rng), u(rng)) : centre;
  switch (kind) {
    case Kind::Rotate: {
      const double most = all ? M_PI : part == Part::Vertex ? M_PI / 4 : M_PI / 12;
      return Similarity::rotation_about(pivot, random_unit(rng), most * u(rng));
    }
    case Kind::Scale:
      return Similarity::scaling(pivot, std::exp((all ? 1.0 : 0.35) * u(rng)));
    case Kind::Move:
      return Similarity::translation((all ? 1.0 : 0.1) * size * Vec3(u(rng), u(rng), u(rng)));
  }
  return {};
}

double distance(const Vec3& a, const Vec3& b) {
  return glm::length(a - b);
}

// Checks one transform of the vertices `chosen` of `before` into `after`, independently of the
// command: moved points are the similarity's images, the rest unchanged bit for bit.
void expect_rigid_part(const Network& before, const Network& after, const std::vector<int>& chosen,
                       const Similarity& t, double size) {
  std::vector<char> moved(before.vertices.size(), 0);
  for (int v : chosen) moved[v] = 1;
  for (std::size_t v = 0; v < before.vertices.size(); ++v) {
    if (moved[v]) {
      EXPECT_LT(distance(after.vertices[v], t.point(before.vertices[v])), 1e-14 * size);
      if (v < before.normals.size() && before.normals[v]) {
        EXPECT_LT(distance(*after.normals[v], t.rotation * *before.normals[v]), 1e-14);
      }
    } else {
      EXPECT_TRUE(same_bits(after.vertices[v], before.vertices[v])) << "vertex " << v;
      if (v < before.normals.size() && before.normals[v]) {
        EXPECT_TRUE(same_bits(*after.normals[v], *before.normals[v]));
      }
    }
  }
  for (std::size_t e = 0; e < before.edges.size(); ++e)
    for (int end = 0; end < 2; ++end) {
      const Vec3 &h0 = before.edges[e].handles[end], &h1 = after.edges[e].handles[end];
      if (moved[before.edges[e].v[end]]) {
        EXPECT_LT(distance(h1, t.point(h0)), 1e-14 * size) << "edge " << e << " end " << end;
      } else {
        EXPECT_TRUE(same_bits(h1, h0)) << "edge " << e << " end " << end;
      }
    }
}

void random_transforms_keep_g1(Kind kind) {
  std::mt19937 rng(17 + static_cast<int>(kind));
  int trials = 0;
  double worst = 0;
  for (const Scene& start : test_scenes()) {
    const Continuity c0 = filled_continuity(*start.network);
    ASSERT_LT(c0.angle_deg, 1e-6);
    ASSERT_EQ(c0.projected, 0u);
    Document doc(start);
    for (int trial = 0; trial < 60; ++trial, ++trials) {
      const Network before = *doc.scene().network;
      const Part part = static_cast<Part>(trial % 3);
      std::vector<int> chosen;
      if (part == Part::Vertex) {
        chosen = {std::uniform_int_distribution<int>(0, int(before.vertices.size()) - 1)(rng)};
      } else if (part == Part::Face) {
        chosen =
            before.faces[std::uniform_int_distribution<int>(0, int(before.faces.size()) - 1)(rng)]
                .loop;
      } else {
        for (std::size_t v = 0; v < before.vertices.size(); ++v) chosen.push_back(int(v));
      }
      std::vector<PointRef> refs;
      Vec3 centre(0);
      for (int v : chosen) {
        refs.push_back(PointRef::vertex(v));
        centre += before.vertices[v];
      }
      centre /= double(chosen.size());
      const double size = network_size(before);
      const Similarity t = random_similarity(kind, part, centre, size, rng);
      doc.execute(std::make_unique<TransformPointsCommand>(refs, t));
      const Network& after = *doc.scene().network;
      expect_rigid_part(before, after, chosen, t, size);
      const Continuity c = filled_continuity(after);
      worst = std::max(worst, c.angle_deg);
      EXPECT_LT(c.angle_deg, 1e-6) << "trial " << trial;
      EXPECT_EQ(c.projected, 0u) << "trial " << trial;
      doc.undo();  // each trial on the network as it was: part transforms of parts accumulate
                   // into folded faces that no designer would keep
    }
  }
  EXPECT_EQ(trials, 120);
  std::printf("largest normal angle over the shared edges in %d trials: %.3g deg\n", trials, worst);
}

TEST(TransformCommand, RandomRotationsOfPartsKeepEveryEdgeG1) {
  random_transforms_keep_g1(Kind::Rotate);
}

TEST(TransformCommand, RandomScalesOfPartsKeepEveryEdgeG1) {
  random_transforms_keep_g1(Kind::Scale);
}

TEST(TransformCommand, RandomMovesOfPartsKeepEveryEdgeG1) {
  random_transforms_keep_g1(Kind::Move);
}

TEST(TransformCommand, UndoRedoAndFileRoundTrip) {
  Document doc(test_scenes()[0]);
  const std::vector<PointRef> refs{PointRef::vertex(4), PointRef::vertex(8)};
  EXPECT_EQ(expect_good_command(
                doc, std::make_unique<TransformPointsCommand>(
                         refs, Similarity::rotation_about(Vec3(1, 1, 0), Vec3(0, 0, 1), 0.3))),
            "rotate 2 points");
  EXPECT_EQ(expect_good_command(doc, std::make_unique<TransformPointsCommand>(
                                         std::vector{PointRef::vertex(0)},
                                         Similarity::scaling(Vec3(1, 1, 0), 1.5))),
            "scale vertex 0");
}

TEST(TransformCommand, RefusesWhatIsNoSimilarityOrNoPoint) {
  Document doc(test_scenes()[0]);
  const std::vector<PointRef> one{PointRef::vertex(1)};
  expect_refused(doc,
                 std::make_unique<TransformPointsCommand>(std::vector<PointRef>{},
                                                          Similarity::translation(Vec3(1))),
                 "nothing selected");
  expect_refused(doc,
                 std::make_unique<TransformPointsCommand>(one, Similarity::scaling(Vec3(0), 0)),
                 "not a rotation");
  expect_refused(
      doc, std::make_unique<TransformPointsCommand>(one, Similarity::translation(Vec3(NAN, 0, 0))),
      "not a rotation");
  Similarity mirror;
  mirror.rotation[0][0] = -1;  // a reflection is not a rotation: it would flip the faces
  expect_refused(doc, std::make_unique<TransformPointsCommand>(one, mirror), "not a rotation");
  expect_refused(doc,
                 std::make_unique<TransformPointsCommand>(std::vector{PointRef::vertex(99)},
                                                          Similarity::translation(Vec3(1))),
                 "no such point");
}

// Every point of a scene (the network's vertices, a GB face's moved centre) turned about an
// axis: the surfaces are the old ones turned, sample by sample (the filling commutes with
// rotations; an independent check that nothing was left behind or turned twice).
TEST(TransformCommand, TurningEverythingTurnsTheSurfaces) {
  Scene start = test_scenes()[0];
  start.network->faces[0].offsets.push_back({.centre = true, .by = Vec3(0.05, -0.02, 0.2)});
  std::vector<PointRef> refs;
  for (std::size_t v = 0; v < start.network->vertices.size(); ++v)
    refs.push_back(PointRef::vertex(int(v)));
  refs.push_back(PointRef::free_point(0, InteriorOffset{.centre = true}));
  const Similarity t = Similarity::rotation_about(Vec3(0.4, -0.3, 0.2), Vec3(1, 2, 0.5), 1.1);
  Document doc(start);
  doc.execute(std::make_unique<TransformPointsCommand>(refs, t));
  TessellationCache cache;
  const SceneSurfaces a = evaluate_scene(start, 2, std::nullopt, cache, "before"),
                      b = evaluate_scene(doc.scene(), 2, std::nullopt, cache, "after");
  ASSERT_EQ(a.surfaces.size(), b.surfaces.size());
  double worst = 0;
  for (std::size_t f = 0; f < a.surfaces.size(); ++f) {
    const Patch &pa = a.surfaces[f].evaluator->patch(), &pb = b.surfaces[f].evaluator->patch();
    for (const Vec2& x : pa.domain().tessellate(6).points)
      worst = std::max(worst, distance(pb.evaluate(x).p, t.point(pa.evaluate(x).p)));
  }
  EXPECT_LT(worst, 1e-12 * network_size(*start.network));
}

}  // namespace
}  // namespace pl::test
