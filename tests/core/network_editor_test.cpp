#include "core/eval/network_editor.hpp"

#include <gtest/gtest.h>

#include <random>
#include <set>

#include "core/base/data_error.hpp"
#include "network_test_util.hpp"

namespace pl {
namespace {

constexpr int kDensity = 12;

std::set<int> faces_touching(const Network& n, int v) {
  std::set<int> out;
  for (std::size_t f = 0; f < n.faces.size(); ++f)
    for (int w : n.faces[f].loop)
      if (w == v) out.insert(int(f));
  return out;
}

// Every sample of every face equals a from-scratch rebuild of the editor's current network, to
// 1e-12 relative to the largest value of that derivative order.
void expect_equals_full_rebuild(const NetworkEditor& ed) {
  TessellationCache cache;
  const NetworkEditor fresh(ed.network(), std::nullopt, kDensity, cache);
  for (int f = 0; f < ed.face_count(); ++f) {
    const auto& a = ed.evaluator(f).jets();
    const auto& b = fresh.evaluator(f).jets();
    ASSERT_EQ(a.size(), b.size());
    EXPECT_EQ(ed.evaluator(f).patch().control_points(),
              fresh.evaluator(f).patch().control_points());
    double scale[3] = {0, 0, 0}, err[3] = {0, 0, 0};
    for (std::size_t i = 0; i < a.size(); ++i) {
      const Vec3 da[6] = {a[i].p, a[i].su, a[i].sv, a[i].suu, a[i].suv, a[i].svv};
      const Vec3 db[6] = {b[i].p, b[i].su, b[i].sv, b[i].suu, b[i].suv, b[i].svv};
      for (int c = 0; c < 6; ++c) {
        const int order = c == 0 ? 0 : c < 3 ? 1 : 2;
        scale[order] = std::max(scale[order], glm::length(db[c]));
        err[order] = std::max(err[order], glm::length(da[c] - db[c]));
      }
    }
    for (int o = 0; o < 3; ++o)
      EXPECT_LE(err[o], 1e-12 * scale[o]) << "face " << f << " order " << o;
  }
}

std::vector<uint64_t> revisions(const NetworkEditor& ed) {
  std::vector<uint64_t> r;
  for (int f = 0; f < ed.face_count(); ++f) r.push_back(ed.evaluator(f).revision());
  return r;
}

// Moving a vertex of valence k changes the k faces around it and nothing else, and gives the
// same samples as rebuilding everything.
TEST(NetworkEditor, MovingAVertexChangesOnlyItsFacesAndEqualsAFullRebuild) {
  TessellationCache cache;
  NetworkEditor ed(test::sphere_blob(true), std::nullopt, kDensity, cache);
  // apex (valence 5), top ring (4), bottom ring vertex 7 = B(1) (3).
  for (auto [v, valence] : {std::pair{0, 5}, {1, 4}, {7, 3}}) {
    const Network before = ed.network();
    ASSERT_EQ(ed.topology().vertex_edges[v].size(), std::size_t(valence));
    const auto rev = revisions(ed);
    const auto up = ed.move_vertex(v, ed.network().vertices[v] + Vec3(0.05, -0.03, 0.04));
    const std::set<int> expected = faces_touching(before, v);
    EXPECT_EQ(expected.size(), std::size_t(valence));
    EXPECT_EQ(std::set<int>(up.faces.begin(), up.faces.end()), expected) << "vertex " << v;
    EXPECT_GT(up.moved_points, 0u);
    const auto rev2 = revisions(ed);
    for (int f = 0; f < ed.face_count(); ++f)
      EXPECT_EQ(rev2[f] != rev[f], expected.count(f) == 1) << "vertex " << v << " face " << f;
    expect_equals_full_rebuild(ed);
  }
  // The handles moved with their vertices, so every tangent plane survived: still G1.
  std::vector<test::FaceSurface> faces;
  for (int f = 0; f < ed.face_count(); ++f)
    faces.push_back({&ed.evaluator(f).patch(), &ed.patch_side(f)});
  EXPECT_LT(test::max_g1_angle_deg(ed.topology(), faces), 1e-6);
}

TEST(NetworkEditor, MovingAHandleChangesTheFacesAtItsVertexAndStaysG1InThePlane) {
  TessellationCache cache;
  NetworkEditor ed(test::sphere_blob(true), std::nullopt, kDensity, cache);
  const int e = 1;  // T(0)-T(1)
  const int v = ed.network().edges[e].v[0];
  // Rotate the handle within the vertex's tangent plane (the sphere's), lengthen it.
  const Vec3 p = ed.network().vertices[v], h = ed.network().edges[e].handles[0];
  const Vec3 d = h - p, n = glm::normalize(p);
  const Vec3 rotated = 1.3 * (std::cos(0.2) * d + std::sin(0.2) * glm::cross(n, d));
  const auto up = ed.move_handle(e, 0, p + rotated);
  const std::set<int> expected = faces_touching(ed.network(), v);
  EXPECT_EQ(std::set<int>(up.faces.begin(), up.faces.end()), expected);
  expect_equals_full_rebuild(ed);
  std::vector<test::FaceSurface> faces;
  for (int f = 0; f < ed.face_count(); ++f)
    faces.push_back({&ed.evaluator(f).patch(), &ed.patch_side(f)});
  EXPECT_LT(test::max_g1_angle_deg(ed.topology(), faces), 1e-6);
  EXPECT_TRUE(ed.projected().empty());
}

TEST(NetworkEditor, ManyMovesStillEqualAFullRebuild) {
  TessellationCache cache;
  NetworkEditor ed(test::height_field(), std::nullopt, kDensity, cache);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> d(-0.05, 0.05);
  std::uniform_int_distribution<int> vertex(0, 8), edge(0, 12), end(0, 1);
  for (int i = 0; i < 40; ++i) {
    if (i % 2 == 0) {
      const int v = vertex(rng);
      ed.move_vertex(v, ed.network().vertices[v] + Vec3(d(rng), d(rng), d(rng)));
    } else {
      const int e = edge(rng), k = end(rng);
      ed.move_handle(e, k, ed.network().edges[e].handles[k] + Vec3(d(rng), d(rng), d(rng)));
    }
  }
  expect_equals_full_rebuild(ed);
}

TEST(NetworkEditor, ADegenerateMoveThrowsAndLeavesTheEditorUnchanged) {
  TessellationCache cache;
  NetworkEditor ed(test::sphere_blob(true), std::nullopt, kDensity, cache, "blob.json");
  const Network before = ed.network();
  const auto rev = revisions(ed);
  const int e = 1, v = ed.network().edges[e].v[0];
  try {
    ed.move_handle(e, 0, ed.network().vertices[v]);
    FAIL() << "expected a DataError";
  } catch (const DataError& err) {
    EXPECT_EQ(err.source(), "blob.json");
    EXPECT_EQ(err.where(), "network.edges[1].handles[0]");
  }
  EXPECT_EQ(ed.network().edges[e].handles[0], before.edges[e].handles[0]);
  EXPECT_EQ(revisions(ed), rev);
  expect_equals_full_rebuild(ed);
}

}  // namespace
}  // namespace pl
