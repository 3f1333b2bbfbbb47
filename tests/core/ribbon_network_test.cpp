// Every face scheme on curve networks: the sample networks of assets/, the test networks, and a
// ring of faces with 3 to 7 sides under a heptagon, each face filled with the scheme (a
// concave face, which the ribbon schemes refuse, keeps gb; a face with more than 4 sides keeps
// auto under gregory). Every shared edge must stay G1 below 1e-6 degrees and every boundary
// within 1e-12 of the network's size, from exact derivatives; and the incremental engine must
// follow a drag like a fresh evaluation, re-filling only the faces at the vertex.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <set>

#include "core/eval/scene_evaluation.hpp"
#include "core/io/scene_io.hpp"
#include "core/network/face_ribbons.hpp"
#include "core/network/gb_face.hpp"
#include "core/scene/network_edit.hpp"
#include "gregory_test_util.hpp"
#include "network_test_util.hpp"
#include "scene_evaluation_test_util.hpp"

namespace pl {
namespace {

// A heptagon cap on the unit sphere (ring T_0..T_6 at latitude 50 degrees) over a band of seven
// faces reaching down to a ring at latitude 15 degrees: band face k runs T_{k+1}, T_k, down to
// the bottom vertex below T_k, east along c_k bottom segments and up again, so it has 3 + c_k
// sides; c = 0..4 gives triangles to heptagons. Open at the bottom (the bottom ring is inside
// the cap above latitude 15 degrees, so every face is convex). Every vertex has its sphere
// normal, so the tangent planes are exact.
Network polygon_ring_network() {
  Network n;
  constexpr int kTop = 7;
  const int c[kTop] = {0, 1, 2, 3, 4, 1, 2};
  const double step = 360.0 / kTop;
  for (int k = 0; k < kTop; ++k) n.vertices.push_back(test::on_sphere(50, step * k));
  std::vector<int> below(kTop + 1);  // the bottom vertex below T_k (index kTop: below T_0)
  for (int k = 0; k < kTop; ++k) {
    if (k == 0) {
      below[0] = int(n.vertices.size());
      n.vertices.push_back(test::on_sphere(15, 0));
    }
    if (c[k] == 0) {  // a triangle: T_{k+1} comes down to the same bottom vertex
      below[k + 1] = below[k];
      continue;
    }
    for (int j = 1; j <= c[k]; ++j) {
      if (k == kTop - 1 && j == c[k]) break;  // back at the first bottom vertex
      n.vertices.push_back(test::on_sphere(15, step * (k + double(j) / c[k])));
    }
    below[k + 1] = k == kTop - 1 ? below[0] : int(n.vertices.size()) - 1;
  }
  std::set<std::pair<int, int>> made;
  const auto need = [&](int a, int b) {
    if (made.insert({std::min(a, b), std::max(a, b)}).second)
      n.edges.push_back(sphere_edge(n.vertices, a, b));
  };
  for (int k = 0; k < kTop; ++k) {
    const int t0 = k, t1 = (k + 1) % kTop;
    std::vector<int> loop{t1, t0};
    if (c[k] == 0) {
      loop.push_back(below[k]);
    } else {  // below[k], the inner bottom vertices, below[k + 1]
      const int first = below[k];
      loop.push_back(first);
      for (int j = 1; j < c[k]; ++j) loop.push_back(first + j);
      loop.push_back(below[k + 1]);
    }
    for (std::size_t i = 0; i < loop.size(); ++i) need(loop[i], loop[(i + 1) % loop.size()]);
    n.faces.push_back({loop, FaceScheme::Auto, "band" + std::to_string(k)});
  }
  std::vector<int> cap;
  for (int k = 0; k < kTop; ++k) cap.push_back(k);
  n.faces.push_back({cap, FaceScheme::Auto, "heptagon"});
  for (const Vec3& v : n.vertices) n.normals.push_back(glm::normalize(v));
  return n;
}

// n with every face given `scheme` where it can take it: a concave face keeps gb under a
// ribbon scheme, a face of more than 4 sides keeps auto under gregory.
Network with_scheme(Network n, FaceScheme scheme) {
  const NetworkTopology topo = validate_network(n, "test");
  std::vector<ProjectedVertex> projected;
  const std::vector<FaceRibbons> ribbons = build_face_ribbons(n, topo, projected);
  for (std::size_t f = 0; f < n.faces.size(); ++f) {
    const std::vector<double> turning = face_turning_angles(ribbons[f]);
    const bool convex = std::all_of(turning.begin(), turning.end(), [](double a) { return a > 0; });
    if (scheme == FaceScheme::Gregory && n.faces[f].loop.size() > 4)
      n.faces[f].scheme = FaceScheme::Auto;
    else if (is_ribbon_scheme(scheme) && !convex)
      n.faces[f].scheme = FaceScheme::GB;
    else
      n.faces[f].scheme = scheme;
    n.faces[f].offsets.clear();
    n.faces[f].degree = 3;
  }
  return n;
}

struct NamedNetwork {
  std::string name;
  Network network;
};

std::vector<NamedNetwork> networks() {
  std::vector<NamedNetwork> out;
  for (const auto& entry :
       std::filesystem::directory_iterator(std::filesystem::path(PATCHLAB_SOURCE_DIR) / "assets")) {
    if (entry.path().extension() != ".json") continue;
    const Scene s = read_scene(entry.path());
    if (s.network) out.push_back({entry.path().filename().string(), *s.network});
  }
  std::sort(out.begin(), out.end(), [](auto& a, auto& b) { return a.name < b.name; });
  out.push_back({"sphere-blob-closed", test::sphere_blob(true)});
  out.push_back({"height-field", test::height_field()});
  out.push_back({"cube-sphere-3", cube_sphere_network(3)});
  out.push_back({"triangles-to-heptagons", polygon_ring_network()});
  return out;
}

TEST(RibbonNetwork, TheRingHasTrianglesToHeptagonsAllConvex) {
  const Network n = polygon_ring_network();
  std::set<std::size_t> sizes;
  for (const NetworkFace& f : n.faces) sizes.insert(f.loop.size());
  EXPECT_EQ(sizes, (std::set<std::size_t>{3, 4, 5, 6, 7}));
  const NetworkTopology topo = validate_network(n, "ring");
  std::vector<ProjectedVertex> projected;
  for (const FaceRibbons& r : build_face_ribbons(n, topo, projected))
    for (double a : face_turning_angles(r)) EXPECT_GT(a, 0);
  EXPECT_TRUE(projected.empty());
}

TEST(RibbonNetwork, EverySchemeIsG1AcrossEverySharedEdgeAndInterpolatesEveryBoundary) {
  for (const NamedNetwork& nn : networks())
    for (FaceScheme scheme : all_face_schemes()) {
      const Network n = with_scheme(nn.network, scheme);
      const NetworkTopology topo = validate_network(n, nn.name);
      const NetworkFilling filling = fill_network(n, topo, std::nullopt, nn.name);
      const auto faces = test::surfaces(filling);
      const double size = test::network_size(n);
      const double dev = test::max_boundary_deviation(n, topo, faces) / size;
      const double angle = test::max_g1_angle_deg(topo, faces);
      const bool exact_planes = filling.projected_vertices.empty();
      std::printf(
          "figure network_%s_%s_max_g1_angle_deg %.3g\n"
          "figure network_%s_%s_max_boundary_deviation_rel %.3g\n",
          nn.name.c_str(), scheme_keyword(scheme).c_str(), angle, nn.name.c_str(),
          scheme_keyword(scheme).c_str(), dev);
      EXPECT_LT(dev, 1e-12) << nn.name << " " << scheme_keyword(scheme);
      // A network whose end tangents leave their vertex planes (projected vertices) cannot be
      // G1 at those vertices by any scheme; along the rest of its edges it still is.
      if (exact_planes) {
        EXPECT_LT(angle, 1e-6) << nn.name << " " << scheme_keyword(scheme);
      }
      for (const FacePatch& fp : filling.faces)
        for (Vec2 x : fp.patch->domain().tessellate(8).points)
          ASSERT_TRUE(test::finite_jet(fp.patch->evaluate(x)))
              << nn.name << " " << scheme_keyword(scheme) << " face " << fp.face;
    }
}

TEST(RibbonNetwork, TheEngineRefillsOnlyTheDraggedFacesAndEqualsAFreshEvaluation) {
  for (FaceScheme scheme : all_face_schemes()) {
    if (!is_ribbon_scheme(scheme)) continue;
    Scene s;
    s.network = with_scheme(test::sphere_blob(true), scheme);
    SceneEvaluation ev(s, 8, std::nullopt);
    const int v = 1;  // a top ring vertex, valence 4
    std::set<int> expected;
    for (std::size_t f = 0; f < s.network->faces.size(); ++f)
      for (int w : s.network->faces[f].loop)
        if (w == v) expected.insert(int(f));
    const Vec3 d(0.04, -0.03, 0.05);
    s.network->vertices[v] += d;
    for (NetworkEdge& e : s.network->edges)
      for (int k = 0; k < 2; ++k)
        if (e.v[k] == v) e.handles[k] += d;
    const SyncStats st = ev.sync(s);
    EXPECT_EQ(std::set<int>(st.changed_surfaces.begin(), st.changed_surfaces.end()), expected)
        << scheme_keyword(scheme);
    test::expect_equals_fresh_evaluation(ev, s, 8);
  }
}

}  // namespace
}  // namespace pl
