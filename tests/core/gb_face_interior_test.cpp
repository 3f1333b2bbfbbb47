// Interior control of network GB faces (core/network/gb_face_interior.hpp): degree and offsets
// of the free points never touch the boundary or the G1 joins, offsets ride on defaults that
// follow the boundary, no offsets at degree 3 is the face without interior control.
#include "core/network/gb_face_interior.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>

#include "core/base/data_error.hpp"
#include "core/domain/concave_polygon.hpp"
#include "core/eval/scene_evaluation.hpp"
#include "core/io/scene_io.hpp"
#include "core/network/face_ribbons.hpp"
#include "core/network/gb_face.hpp"
#include "core/network/incremental_filling.hpp"
#include "core/patch/control_net_topology.hpp"
#include "core/patch/gb/default_net.hpp"
#include "core/patch/gb/gb_interior_patch.hpp"
#include "core/patch/gb/ribbon_elevation.hpp"
#include "network_test_util.hpp"

namespace pl {
namespace {

using test::network_size;

Network load_network(const std::string& name) {
  const std::string path = std::string(PATCHLAB_SOURCE_DIR) + "/assets/" + name;
  std::ifstream in(path);
  EXPECT_TRUE(in) << path;
  std::stringstream ss;
  ss << in.rdbuf();
  return *parse_scene(ss.str(), path).network;
}

// Every face GB (the sample networks' triangles and quads too), so every face has an interior.
Network all_gb(Network n) {
  for (NetworkFace& f : n.faces) f.scheme = FaceScheme::GB;
  return n;
}

struct Measure {
  double deviation = 0;  // boundary against the edges, relative to the network's size
  double angle_deg = 0;  // largest normal angle across shared edges
};
Measure measure(const Network& n) {
  const NetworkTopology topo = validate_network(n, "test");
  const NetworkFilling filling = fill_network(n, topo, std::nullopt, "test");
  const auto faces = test::surfaces(filling);
  return {test::max_boundary_deviation(n, topo, faces) / network_size(n),
          test::max_g1_angle_deg(topo, faces)};
}

// The free points of a face of n sides and degree d, each once (the .gbp stored names).
std::vector<InteriorOffset> free_points(int n, int d) {
  std::vector<InteriorOffset> out{InteriorOffset{.centre = true}};
  for (int k = 2; k < gb_face_layers(d); ++k)
    for (int i = 0; i < n; ++i)
      for (int j = k; j <= d - 1 - k; ++j) {
        InteriorOffset o{.side = i, .j = j, .layer = k};
        if (is_free_interior_point(d, o)) out.push_back(o);
      }
  return out;
}

std::vector<Vec2> domain_samples(const Patch& p) {
  std::vector<Vec2> xs;
  for (const Vec2& x : p.domain().tessellate(12).points) xs.push_back(x);
  return xs;
}

// The sample networks with GB faces (every assets/*.json whose network has a face filled GB:
// among them the pentagon and hexagon of gb-hole-filling.json, which share an edge, and the
// concave faces of gb-concave-l.json), and the sphere blob with every face GB.
std::vector<std::pair<std::string, Network>> networks_with_gb_faces() {
  std::vector<std::pair<std::string, Network>> out;
  std::vector<std::filesystem::path> files;
  for (const auto& e :
       std::filesystem::directory_iterator(std::string(PATCHLAB_SOURCE_DIR) + "/assets"))
    if (e.path().extension() == ".json") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  for (const auto& path : files) {
    std::ifstream in(path);
    std::stringstream ss;
    ss << in.rdbuf();
    const Scene scene = parse_scene(ss.str(), path.string());
    if (!scene.network) continue;
    for (const NetworkFace& f : scene.network->faces)
      if (resolve_scheme(f, std::nullopt) == FaceScheme::GB) {
        out.emplace_back(path.filename().string(), *scene.network);
        break;
      }
  }
  out.emplace_back("sphere-blob, every face GB", all_gb(test::sphere_blob(true)));
  return out;
}

// 200 random moves of free points per network, followed by the incremental engine (the editor's
// drag path); after every move the boundaries are measured against the edge curves and the
// normals across every shared edge from both faces' patches (test::max_g1_angle_deg).
TEST(GBFaceInterior, RandomMovesOfFreePointsKeepBoundariesAndG1) {
  std::mt19937 rng(7);
  const auto networks = networks_with_gb_faces();
  ASSERT_GE(networks.size(), 4u);  // default, gb-concave-l, gb-hole-filling, gb-interior + blob
  for (auto [file, n] : networks) {
    const double size = network_size(n);
    std::vector<int> gb;
    for (std::size_t f = 0; f < n.faces.size(); ++f)
      if (resolve_scheme(n.faces[f], std::nullopt) == FaceScheme::GB) {
        n.faces[f].degree = 5 + int(f % 3);  // 5, 6, 7: free rows and the centre
        gb.push_back(int(f));
      }
    Scene scene;
    scene.network = n;
    SceneEvaluation ev(scene, 8, std::nullopt);
    Measure worst;
    std::uniform_real_distribution<double> u(-0.1, 0.1);
    constexpr int kMoves = 200;
    std::size_t moved = 0;
    for (int m = 0; m < kMoves; ++m) {
      NetworkFace& face = scene.network->faces[gb[rng() % gb.size()]];
      const auto points = free_points(int(face.loop.size()), face.degree);
      InteriorOffset o = points[rng() % points.size()];
      const auto same = std::find_if(face.offsets.begin(), face.offsets.end(), [&](auto& x) {
        return x.centre == o.centre && x.side == o.side && x.j == o.j && x.layer == o.layer;
      });
      const Vec3 by(u(rng) * size, u(rng) * size, u(rng) * size);
      if (same != face.offsets.end()) {
        same->by += by;
      } else {
        o.by = by;
        face.offsets.push_back(o);
      }
      moved += ev.sync(scene).moved_points;
      std::vector<test::FaceSurface> faces;
      for (const SceneSurface& s : ev.surfaces().surfaces)
        if (s.face >= 0) faces.push_back({&s.evaluator->patch(), &s.patch_side});
      const NetworkTopology& topo = ev.filling().topology();
      worst.deviation = std::max(worst.deviation,
                                 test::max_boundary_deviation(*scene.network, topo, faces) / size);
      worst.angle_deg = std::max(worst.angle_deg, test::max_g1_angle_deg(topo, faces));
    }
    // and the same network filled from scratch
    const Measure scratch = measure(*scene.network);
    std::printf(
        "%s: %d random free-point moves (%zu points moved incrementally), boundary %.3g "
        "(relative), G1 %.3g deg; from scratch %.3g, %.3g deg\n",
        file.c_str(), kMoves, moved, worst.deviation, worst.angle_deg, scratch.deviation,
        scratch.angle_deg);
    EXPECT_LT(worst.deviation, 1e-12) << file;
    EXPECT_LT(worst.angle_deg, 1e-6) << file;
    EXPECT_LT(scratch.deviation, 1e-12) << file;
    EXPECT_LT(scratch.angle_deg, 1e-6) << file;
  }
}

TEST(GBFaceInterior, ZeroOffsetsAtDegreeThreeAreTheFaceWithoutInteriorControl) {
  for (const char* file : {"gb-hole-filling.json", "gb-concave-l.json"}) {
    const Network n = all_gb(load_network(file));
    const NetworkTopology topo = validate_network(n, "test");
    std::vector<ProjectedVertex> projected;
    const auto ribbons = build_face_ribbons(n, topo, projected);
    for (std::size_t f = 0; f < n.faces.size(); ++f) {
      const auto today = gb_face_patch(ribbons[f]);
      const InteriorOffset zero{.centre = true};
      const auto with = gb_face_patch(ribbons[f], 3, std::span(&zero, 1));
      double worst = 0, scale = network_size(n);
      for (const Vec2& x : domain_samples(*today)) {
        const SurfaceJet a = today->evaluate(x), b = with->evaluate(x);
        worst = std::max(
            {worst, glm::length(a.p - b.p), glm::length(a.su - b.su), glm::length(a.sv - b.sv)});
      }
      EXPECT_LT(worst / scale, 1e-12) << file << " face " << f;
      // and through the basis (S = sum phi_k C_k holds for the centred form)
      std::vector<Jet> phi(with->size());
      const Vec2 x = today->domain().interior_point();
      with->basis(x, phi);
      EXPECT_LT(glm::length(combine(with->control_points(), phi).p - today->evaluate(x).p) / scale,
                1e-12);
    }
  }
}

// After a vertex move every free point of the face's patch is its new default plus its stored
// offset (the pentagon of gb-hole-filling and the concave hexagon of gb-concave-l, every free
// point offset), and the network stays G1.
TEST(GBFaceInterior, OffsetsFollowTheBoundary) {
  std::mt19937 rng(19);
  std::uniform_real_distribution<double> u(-0.05, 0.05);
  for (const char* file : {"gb-hole-filling.json", "gb-concave-l.json"}) {
    Network n = load_network(file);
    NetworkFace& face = n.faces[0];
    face.scheme = FaceScheme::GB;
    face.degree = 6;
    const int sides = int(face.loop.size());
    const double size = network_size(n);
    for (const InteriorOffset& p : free_points(sides, 6)) {
      InteriorOffset o = p;
      o.by = Vec3(u(rng), u(rng), u(rng)) * size;
      face.offsets.push_back(o);
    }
    const auto check = [&](const Network& net) {
      const NetworkTopology topo = validate_network(net, "test");
      std::vector<ProjectedVertex> projected;
      const auto ribbons = build_face_ribbons(net, topo, projected);
      const std::vector<Vec3> defaults = gb_face_default_net(ribbons[0], 6);
      const auto patch = gb_face_patch(ribbons[0], 6, face.offsets);
      const auto& c = dynamic_cast<const GBInteriorPatch&>(*patch);
      EXPECT_EQ(c.free_points().size(), face.offsets.size()) << file;
      double worst = 0;
      for (const InteriorOffset& o : face.offsets) {
        const std::size_t k = interior_point_index(sides, 6, o);
        worst = std::max(worst, glm::length(c.control_point(k) - (defaults[k] + o.by)) / size);
      }
      return std::pair{worst, defaults};
    };
    const auto [before, defaults_before] = check(n);
    // Move a vertex of the face with its edges' handles.
    const int v = face.loop[1];
    const Vec3 d(0.07, -0.04, 0.11);
    n.vertices[v] += d;
    for (NetworkEdge& e : n.edges)
      for (int s = 0; s < 2; ++s)
        if (e.v[s] == v) e.handles[s] += d;
    const auto [after, defaults_after] = check(n);
    EXPECT_LT(before, 1e-12) << file;
    EXPECT_LT(after, 1e-12) << file;
    EXPECT_GT(glm::length(defaults_after[0] - defaults_before[0]), 1e-3) << file;  // they moved
    const Measure m = measure(n);
    EXPECT_LT(m.deviation, 1e-12) << file;
    EXPECT_LT(m.angle_deg, 1e-6) << file;
  }
}

// A planar boundary with planar cross-boundary data: every default lies on the plane (the
// default-net rule is affine), so the face is the plane at every degree.
TEST(GBFaceInterior, PlanarFaceStaysPlanarAtEveryDegree) {
  Network n;
  for (int i = 0; i < 5; ++i)
    n.vertices.push_back({std::cos(i * 2 * M_PI / 5), std::sin(i * 2 * M_PI / 5), 0});
  for (int i = 0; i < 5; ++i) {
    const Vec3 a = n.vertices[i], b = n.vertices[(i + 1) % 5];
    n.edges.push_back({{i, (i + 1) % 5}, {a + (b - a) / 3.0, b - (b - a) / 3.0}, ""});
  }
  n.faces.push_back(NetworkFace({0, 1, 2, 3, 4}));
  for (int d = 3; d <= 9; ++d) {
    n.faces[0].degree = d;
    const NetworkTopology topo = validate_network(n, "test");
    const NetworkFilling filling = fill_network(n, topo, std::nullopt, "test");
    double worst = 0;
    for (const Vec3& p : filling.faces[0].patch->control_points())
      worst = std::max(worst, std::abs(p.z));
    for (const Vec2& x : domain_samples(*filling.faces[0].patch))
      worst = std::max(worst, std::abs(filling.faces[0].patch->evaluate(x).p.z));
    EXPECT_LT(worst, 1e-14) << "degree " << d;
  }
}

// Changing the degree of every face, with offsets re-fitted by gb_face_offsets_for_degree from
// degree 5 (random offsets on every free point), keeps the boundary curves and the normals along
// every side: those of the degree-5 faces, measured side by side.
TEST(GBFaceInterior, ChangingTheDegreeKeepsBoundariesAndSideNormals) {
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> u(-0.05, 0.05);
  for (const char* file : {"gb-hole-filling.json", "gb-concave-l.json"}) {
    Network base = all_gb(load_network(file));
    const double size = network_size(base);
    for (NetworkFace& f : base.faces) {
      f.degree = 5;
      for (InteriorOffset o : free_points(int(f.loop.size()), 5)) {
        o.by = Vec3(u(rng), u(rng), u(rng)) * size;
        f.offsets.push_back(o);
      }
    }
    const NetworkTopology topo = validate_network(base, "test");
    std::vector<ProjectedVertex> projected;
    const auto ribbons = build_face_ribbons(base, topo, projected);
    const NetworkFilling five = fill_network(base, topo, std::nullopt, "test");
    for (int d = 3; d <= 9; ++d) {
      Network n = base;
      for (std::size_t f = 0; f < n.faces.size(); ++f) {
        n.faces[f].offsets = gb_face_offsets_for_degree(ribbons[f], 5, base.faces[f].offsets, d);
        n.faces[f].degree = d;
      }
      const NetworkFilling changed = fill_network(n, topo, std::nullopt, "test");
      const auto faces = test::surfaces(changed), before = test::surfaces(five);
      double angle = 0;
      for (std::size_t f = 0; f < n.faces.size(); ++f)
        for (std::size_t i = 0; i < n.faces[f].loop.size(); ++i)
          for (int k = 0; k <= test::kEdgeSamples; ++k) {
            const double t = double(k) / test::kEdgeSamples;
            angle = std::max(angle, test::angle_between_deg(
                                        test::side_normal(faces[f], topo, int(f), int(i), t),
                                        test::side_normal(before[f], topo, int(f), int(i), t)));
          }
      EXPECT_LT(test::max_boundary_deviation(n, topo, faces) / size, 1e-12)
          << file << " degree " << d;
      EXPECT_LT(angle, 1e-6) << file << " degree " << d;
      EXPECT_LT(test::max_g1_angle_deg(topo, faces), 1e-6) << file << " degree " << d;
    }
  }
}

// With no offsets the face is its default filling at every degree: the cubic face without
// interior control (gb_face_patch of the ribbons), on a dense sample, convex and concave faces.
TEST(GBFaceInterior, ZeroOffsetsAreTheDefaultFillingAtEveryDegree) {
  for (const char* file : {"gb-hole-filling.json", "gb-concave-l.json"}) {
    const Network n = all_gb(load_network(file));
    const NetworkTopology topo = validate_network(n, "test");
    std::vector<ProjectedVertex> projected;
    const auto ribbons = build_face_ribbons(n, topo, projected);
    const double size = network_size(n);
    for (std::size_t f = 0; f < n.faces.size(); ++f) {
      const auto plain = gb_face_patch(ribbons[f]);
      const std::vector<Vec2> xs = plain->domain().tessellate(24).points;
      for (int d = 3; d <= 9; ++d) {
        // every free point named with a zero offset
        std::vector<InteriorOffset> zero = free_points(int(n.faces[f].loop.size()), d);
        const auto face = gb_face_patch(ribbons[f], d, zero);
        double worst = 0;
        for (const Vec2& x : xs) {
          const SurfaceJet a = plain->evaluate(x), b = face->evaluate(x);
          worst = std::max({worst, glm::length(a.p - b.p), glm::length(a.su - b.su),
                            glm::length(a.sv - b.sv), glm::length(a.suu - b.suu)});
        }
        EXPECT_LT(worst / size, 1e-12) << file << " face " << f << " degree " << d;
      }
    }
  }
}

std::string face_scene(const std::string& face_extra, int sides = 5) {
  std::ostringstream s;
  s << R"({"patchlab": 1, "network": {"vertices": [)";
  for (int i = 0; i < sides; ++i)
    s << (i ? "," : "") << "[" << std::cos(i * 2 * M_PI / sides) << ","
      << std::sin(i * 2 * M_PI / sides) << ",0]";
  s << R"(], "edges": [)";
  for (int i = 0; i < sides; ++i) {
    const int j = (i + 1) % sides;
    const Vec3 a(std::cos(i * 2 * M_PI / sides), std::sin(i * 2 * M_PI / sides), 0),
        b(std::cos(j * 2 * M_PI / sides), std::sin(j * 2 * M_PI / sides), 0);
    const Vec3 h1 = a + (b - a) / 3.0, h2 = b - (b - a) / 3.0;
    s << (i ? "," : "") << R"({"v": [)" << i << "," << j << R"(], "handles": [[)" << h1.x << ","
      << h1.y << ",0],[" << h2.x << "," << h2.y << ",0]]}";
  }
  s << R"(], "faces": [{"loop": [)";
  for (int i = 0; i < sides; ++i) s << (i ? "," : "") << i;
  s << "]" << face_extra << "}]}}";
  return s.str();
}

std::string read_error(const std::string& text) {
  try {
    parse_scene(text, "t.json");
  } catch (const DataError& e) {
    return e.what();
  }
  return "";
}

TEST(GBFaceInterior, SceneKeysRoundTrip) {
  const Scene s =
      parse_scene(face_scene(R"(, "degree": 6, "offsets": [{"at": "center", "by": [0, 0, 0.5]},
                 {"at": [4, 3, 2], "by": [0.125, 0, 0]}])"),
                  "t.json");
  const NetworkFace& f = s.network->faces[0];
  EXPECT_EQ(f.degree, 6);
  ASSERT_EQ(f.offsets.size(), 2u);
  EXPECT_TRUE(f.offsets[0].centre);
  EXPECT_EQ(f.offsets[1].side, 4);
  EXPECT_EQ(f.offsets[1].j, 3);
  EXPECT_EQ(f.offsets[1].layer, 2);
  EXPECT_EQ(f.offsets[1].by, Vec3(0.125, 0, 0));
  const Scene back = parse_scene(scene_to_json(s), "again.json");
  EXPECT_EQ(*back.network, *s.network);
  // Degree 3 and no offsets write nothing new.
  const Scene plain = parse_scene(face_scene(""), "t.json");
  EXPECT_EQ(scene_to_json(plain).find("degree"), std::string::npos);
}

TEST(GBFaceInterior, BadInteriorKeysAreLocatedErrors) {
  const auto expect = [](const std::string& extra, const std::string& where,
                         const std::string& what, int sides = 5) {
    const std::string e = read_error(face_scene(extra, sides));
    EXPECT_NE(e.find(where), std::string::npos) << e;
    EXPECT_NE(e.find(what), std::string::npos) << e;
  };
  expect(R"(, "degree": 2)", "network.faces[0].degree", "");
  expect(R"(, "degree": 16)", "network.faces[0].degree", "");
  expect(R"(, "degree": 5)", "network.faces[0].degree", "Gregory face has no free interior", 4);
  expect(R"(, "scheme": "gregory", "offsets": [])", "network.faces[0].offsets",
         "Gregory face has no free interior", 4);
  expect(R"(, "degree": 6, "offsets": [{"at": [0, 1, 2], "by": [0,0,0]}])",
         "network.faces[0].offsets[0].at", "not free");
  expect(R"(, "degree": 6, "offsets": [{"at": [0, 3, 1], "by": [0,0,0]}])",
         "network.faces[0].offsets[0].at", "not free");
  expect(R"(, "degree": 6, "offsets": [{"at": [5, 3, 2], "by": [0,0,0]}])",
         "network.faces[0].offsets[0].at", "side 5 does not exist");
  expect(R"(, "degree": 4, "offsets": [{"at": [0, 2, 2], "by": [0,0,0]}])",
         "network.faces[0].offsets[0].at", "layer 2 does not exist");
  expect(R"(, "offsets": [{"at": "middle", "by": [0,0,0]}])", "network.faces[0].offsets[0].at",
         "center");
  // [0, 4, 2] and [1, 2, 2] name one shared corner-block point of a degree-6 face.
  expect(R"(, "degree": 6, "offsets": [{"at": [0, 4, 2], "by": [0,0,0]},
            {"at": [1, 2, 2], "by": [1,0,0]}])",
         "network.faces[0].offsets[1].at", "already has an offset");
  expect(R"(, "offsets": [{"at": "center"}])", "network.faces[0].offsets[0]", "by");
  expect(R"(, "offsets": [{"at": "center", "by": [0,0,0], "x": 1}])", "network.faces[0].offsets[0]",
         "x");
}

// The engine follows interior edits: an offset change of a face whose patch is the interior form
// refills nothing (interior_edited lists the face); moving the patch it had by the listed moves
// gives the from-scratch filling's patch, point for point. A degree change is a refill.
TEST(GBFaceInterior, IncrementalFillingListsInteriorEditsWithoutRefilling) {
  Network n = load_network("gb-hole-filling.json");
  n.faces[0].degree = 6;
  IncrementalFilling filling(std::nullopt, "t.json");
  const FillingUpdate first = filling.update(n);
  std::unique_ptr<Patch> patch = first.refilled.at(0).patch->clone();
  n.faces[0].offsets.push_back({.side = 2, .j = 3, .layer = 2, .by = {0, 0, 0.2}});
  n.faces[0].offsets.push_back({.centre = true, .by = {0.1, 0, 0}});
  const FillingUpdate up = filling.update(n);
  EXPECT_TRUE(up.refilled.empty());
  EXPECT_EQ(up.interior_edited, std::vector<int>{0});
  EXPECT_EQ(up.previous_face[0], 0);
  const auto moves = interior_point_moves(dynamic_cast<const GBInteriorPatch&>(*patch), n.faces[0]);
  EXPECT_EQ(moves.size(), 2u);
  for (const InteriorPointMove& m : moves) patch->set_control_point(m.index, m.position);
  const NetworkFilling scratch = fill_network(n, validate_network(n, "t"), std::nullopt, "t");
  const Patch& b = *scratch.faces[0].patch;
  ASSERT_EQ(patch->control_points(), b.control_points());
  ASSERT_EQ(filling.build(0).patch->control_points(), b.control_points());
  for (const Vec2& x : domain_samples(b)) EXPECT_EQ(patch->evaluate(x).p, b.evaluate(x).p);
  n.faces[0].degree = 7;
  const FillingUpdate raised = filling.update(n);
  ASSERT_EQ(raised.refilled.size(), 1u);
  EXPECT_EQ(raised.refilled[0].face, 0);
  EXPECT_TRUE(raised.interior_edited.empty());
}

// The face's patch shows its degree-d net: the net of a .gbp patch with the same points, and
// nothing of what lies behind it (the default filling's points, the free points' defaults).
TEST(GBFaceInterior, ThePatchShowsItsDegreeNet) {
  Network n = load_network("gb-hole-filling.json");
  const NetworkTopology topo = validate_network(n, "test");
  std::vector<ProjectedVertex> projected;
  const auto ribbons = build_face_ribbons(n, topo, projected);
  const InteriorOffset o{.side = 1, .j = 3, .layer = 2, .by = {0, 0, 0.1}};
  const auto patch = gb_face_interior_patch(ribbons[0], 6, std::span(&o, 1));
  const std::vector<Vec3> net(patch->control_points().begin(),
                              patch->control_points().begin() + patch->net_size());
  const GBPatch gbp(5, 6, net);
  const ControlNetTopology t = control_net_topology(*patch);
  EXPECT_EQ(t.segments, control_net_topology(gbp).segments);
  for (std::size_t k = 0; k < patch->size(); ++k) {
    EXPECT_EQ(t.is_vector[k], k >= patch->net_size()) << k;
    if (k < patch->net_size()) {
      EXPECT_EQ(patch->kind(k), gbp.kind(k)) << k;
    }
  }
  // Rings 0 and 1 are the default net's; the moved point sits at its default plus its offset.
  const std::vector<Vec3> defaults = gb_face_default_net(ribbons[0], 6);
  for (std::size_t k = 0; k < patch->net_size(); ++k) {
    const Vec3 want = k == interior_point_index(5, 6, o) ? defaults[k] + o.by : defaults[k];
    EXPECT_EQ(patch->control_point(k), want) << k;
  }
}

// One face over a planar polygon lifted to z = 0.1 x y, straight cubic edges, degree d.
Network lifted_face(const std::vector<Vec2>& polygon) {
  Network net;
  const int n = static_cast<int>(polygon.size());
  for (const Vec2& p : polygon) net.vertices.push_back({p.x, p.y, 0.1 * p.x * p.y});
  NetworkFace f;
  for (int i = 0; i < n; ++i) {
    const Vec3 p = net.vertices[i], q = net.vertices[(i + 1) % n];
    net.edges.push_back({{i, (i + 1) % n}, {p + (q - p) / 3.0, p + 2.0 * (q - p) / 3.0}, ""});
    f.loop.push_back(i);
  }
  f.scheme = FaceScheme::GB;
  net.faces.push_back(f);
  return net;
}

// The displacement S - F of a face with offsets is the degree-d independent-ribbon patch of the
// net with the offsets minus the same patch of the net without them (the blends are linear in
// the points), built here from whole nets: rows k of ribbon i from the .gbp net, and on the sides
// behind a reflex corner the rows elevated until l_i >= d (ribbon_with_layer), as a face filled
// with a degree-d net would have them. Checked on a pentagon (plain sides) and on a notch and a
// U, whose walls need those extra layers; the boundary and the cross-boundary normals stay F's.
TEST(GBFaceInterior, DisplacementIsTheDegreeNetsBlendsOfTheOffsets) {
  const std::vector<Vec2> pentagon = {
      {1, 0}, {0.309, 0.951}, {-0.809, 0.588}, {-0.809, -0.588}, {0.309, -0.951}};
  const std::vector<Vec2> notch = {{0, 0},      {1, 0},      {1, 1},    {0.75, 1},
                                   {0.75, 0.7}, {0.25, 0.7}, {0.25, 1}, {0, 1}};
  const std::vector<Vec2> u = {{0, 0}, {3, 0}, {3, 2}, {2, 2}, {2, 0.8}, {1, 0.8}, {1, 2}, {0, 2}};
  std::mt19937 rng(29);
  std::uniform_real_distribution<double> r(-0.1, 0.1);
  int deep_faces = 0;
  for (const auto& [poly, name] :
       {std::pair{pentagon, "pentagon"}, std::pair{notch, "notch"}, std::pair{u, "U"}}) {
    const Network net = lifted_face(poly);
    const NetworkTopology topo = validate_network(net, name);
    std::vector<ProjectedVertex> projected;
    const FaceRibbons ribbons = build_face_ribbons(net, topo, projected)[0];
    const int n = int(poly.size());
    for (int d : {5, 6, 7}) {
      std::vector<InteriorOffset> offsets;
      for (InteriorOffset o : free_points(n, d))
        if (!o.centre) {
          o.by = Vec3(r(rng), r(rng), r(rng));
          offsets.push_back(o);
        }
      const auto face = gb_face_interior_patch(ribbons, d, offsets);
      const GBRibbonPatch& filling = face->filling();
      const std::vector<int> deep = GBRibbonPatch::sides_without_positive_pair(filling.polygon());
      deep_faces += !deep.empty();
      const auto ribbon_patch = [&](const std::vector<Vec3>& gbp) {
        const int l = gb_face_layers(d);
        std::vector<std::vector<std::vector<Vec3>>> rows(n);
        for (int i = 0; i < n; ++i) {
          for (int k = 0; k < l; ++k) {
            rows[i].emplace_back();
            for (int j = 0; j <= d; ++j) rows[i][k].push_back(gbp[gb_net_index(n, d, i, j, k)]);
          }
          if (std::find(deep.begin(), deep.end(), i) != deep.end())
            while (int(rows[i].size()) < d) rows[i] = ribbon_with_layer(rows[i]);
        }
        return GBRibbonPatch(filling.polygon(), rows);
      };
      const std::vector<Vec3> defaults = gb_face_default_net(ribbons, d);
      std::vector<Vec3> moved = defaults;
      for (const InteriorOffset& o : offsets) moved[interior_point_index(n, d, o)] += o.by;
      const GBRibbonPatch with = ribbon_patch(moved), without = ribbon_patch(defaults);
      double worst = 0;
      for (const Vec2& x : filling.domain().tessellate(16).points) {
        const SurfaceJet s = face->evaluate(x), f = filling.evaluate(x);
        const SurfaceJet a = with.evaluate(x), b = without.evaluate(x);
        worst = std::max({worst, glm::length((s.p - f.p) - (a.p - b.p)),
                          glm::length((s.su - f.su) - (a.su - b.su)),
                          glm::length((s.sv - f.sv) - (a.sv - b.sv))});
      }
      // Along every side the face is its default filling: position and normal.
      double dev = 0, angle = 0;
      for (int i = 0; i < n; ++i)
        for (int k = 0; k <= 32; ++k) {
          const Vec2 x = filling.domain().side_point(i, k / 32.0);
          const SurfaceJet s = face->evaluate(x), f = filling.evaluate(x);
          dev = std::max(dev, glm::length(s.p - f.p));
          angle = std::max(angle,
                           test::angle_between_deg(glm::cross(s.su, s.sv), glm::cross(f.su, f.sv)));
        }
      EXPECT_LT(worst, 1e-12) << name << " degree " << d;
      EXPECT_LT(dev, 1e-12) << name << " degree " << d;
      EXPECT_LT(angle, 1e-6) << name << " degree " << d;
    }
  }
  EXPECT_GE(deep_faces, 6);  // the notch and the U at every degree have sides with more layers
}

// The central point's weight phi_0 on the faces it must serve: the concave L of
// gb-concave-l.json, a notched square, a U and a convex pentagon (its regular-pentagon domain).
struct CentreCase {
  std::string name;
  std::unique_ptr<GBInteriorPatch> face;   // degree 3, a central offset
  std::unique_ptr<GBRibbonPatch> filling;  // the same face without it
};
std::vector<CentreCase> centre_cases(const Vec3& by) {
  const std::vector<Vec2> pentagon = {
      {1, 0}, {0.309, 0.951}, {-0.809, 0.588}, {-0.809, -0.588}, {0.309, -0.951}};
  const std::vector<Vec2> notch = {{0, 0},      {1, 0},      {1, 1},    {0.75, 1},
                                   {0.75, 0.7}, {0.25, 0.7}, {0.25, 1}, {0, 1}};
  const std::vector<Vec2> u = {{0, 0}, {3, 0}, {3, 2}, {2, 2}, {2, 0.8}, {1, 0.8}, {1, 2}, {0, 2}};
  std::vector<std::pair<std::string, Network>> nets = {{"L", load_network("gb-concave-l.json")},
                                                       {"notch", lifted_face(notch)},
                                                       {"U", lifted_face(u)},
                                                       {"pentagon", lifted_face(pentagon)}};
  const InteriorOffset o{.centre = true, .by = by};
  std::vector<CentreCase> out;
  for (auto& [name, net] : nets) {
    const NetworkTopology topo = validate_network(net, name);
    std::vector<ProjectedVertex> projected;
    const FaceRibbons ribbons = build_face_ribbons(net, topo, projected)[0];
    auto face = gb_face_interior_patch(ribbons, 3, std::span(&o, 1));
    auto filling = std::make_unique<GBRibbonPatch>(face->filling());
    out.push_back({name, std::move(face), std::move(filling)});
  }
  return out;
}

double boundary_distance(const std::vector<Vec2>& polygon, Vec2 x) {
  double d = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < polygon.size(); ++i)
    d = std::min(
        d, segment_distance(x, polygon[(i + polygon.size() - 1) % polygon.size()], polygon[i]));
  return d;
}

// phi_0 vanishes with its first derivatives on every side, measured without its formula or its
// jets: at distance e from a side inside the face it is O(e^2) (halving e quarters it), and the
// surface with a central offset keeps the default filling's boundary and normals along every side.
TEST(GBFaceInterior, CentralWeightVanishesWithItsFirstDerivativesOnEverySide) {
  for (const CentreCase& c : centre_cases(Vec3(0, 0, 0.4))) {
    const ConcavePolygonDomain& domain = c.filling->polygon();
    const std::vector<Vec2>& poly = domain.vertices();
    const int n = int(poly.size());
    double on_side = 0, slope = 0, worst_ratio = 0, dev = 0, angle = 0;
    for (int i = 0; i < n; ++i) {
      const Vec2 a = poly[(i + n - 1) % n], b = poly[i];
      const Vec2 e = glm::normalize(b - a), inward(-e.y, e.x);  // sides run counter-clockwise
      for (int k = 0; k <= 20; ++k) {
        const double t = 0.05 + 0.9 * k / 20.0;
        const Vec2 x = domain.side_point(i, t);
        on_side = std::max(on_side, std::abs(c.face->free_blend(0, x).f));
        const double e1 = 2e-4, p1 = c.face->free_blend(0, x + e1 * inward).f,
                     p2 = c.face->free_blend(0, x + 0.5 * e1 * inward).f;
        slope = std::max(slope, p1 / e1);
        worst_ratio = std::max(worst_ratio, std::abs(p2 / p1 - 0.25));
        const SurfaceJet s = c.face->evaluate(x), f = c.filling->evaluate(x);
        dev = std::max(dev, glm::length(s.p - f.p));
        angle = std::max(angle,
                         test::angle_between_deg(glm::cross(s.su, s.sv), glm::cross(f.su, f.sv)));
      }
    }
    std::printf(
        "%s: phi_0 on the sides %.3g, phi_0(e)/e at e = 2e-4 %.3g, |phi(e/2)/phi(e) - "
        "1/4| %.3g; surface vs default along the sides %.3g, %.3g deg\n",
        c.name.c_str(), on_side, slope, worst_ratio, dev, angle);
    EXPECT_LT(on_side, 1e-15) << c.name;
    EXPECT_LT(slope, 1e-2) << c.name;        // a first-order term would give O(1)
    EXPECT_LT(worst_ratio, 0.01) << c.name;  // quadratic: phi(e/2) = phi(e) / 4
    EXPECT_LT(dev, 1e-12) << c.name;
    EXPECT_LT(angle, 1e-6) << c.name;
  }
}

// phi_0 is positive inside, at most 1, reaches 1 (its largest value), and its largest value lies
// well inside the face: at least 3/4 of the inradius from the boundary (the old weight, a product
// of the mean value h_i^2, peaked at under 0.6 of it on the concave faces, beside a reflex
// corner). Its jets match finite differences of its values. The central offset moves the surface
// by phi_0 times the offset.
TEST(GBFaceInterior, CentralWeightPeaksWellInsideTheFace) {
  const Vec3 by(0.1, -0.2, 0.4);
  for (const CentreCase& c : centre_cases(by)) {
    const ConcavePolygonDomain& domain = c.filling->polygon();
    const std::vector<Vec2>& poly = domain.vertices();
    double inradius = 0, best = -1, least_inside = 1, worst_move = 0, worst_jet = 0;
    Vec2 peak(0);
    for (const Vec2& x : domain.tessellate(96).points) {
      const double d = boundary_distance(poly, x);
      inradius = std::max(inradius, d);
      const double phi = c.face->free_blend(0, x).f;
      if (phi > best) best = phi, peak = x;
      if (d > 1e-9) least_inside = std::min(least_inside, phi);
      const Vec3 moved = c.face->evaluate(x).p - c.filling->evaluate(x).p;
      worst_move = std::max(worst_move, glm::length(moved - phi * by));
    }
    for (const Vec2& x : domain.tessellate(6).points) {
      if (boundary_distance(poly, x) < 0.05 * inradius) continue;
      const double h = 1e-5;
      const Jet j = c.face->free_blend(0, x);
      const auto at = [&](double du, double dv) {
        return c.face->free_blend(0, x + Vec2(du, dv)).f;
      };
      const double fu = (at(h, 0) - at(-h, 0)) / (2 * h), fv = (at(0, h) - at(0, -h)) / (2 * h);
      const double hh = 1e-4;
      const double fuu = (at(hh, 0) - 2 * j.f + at(-hh, 0)) / (hh * hh),
                   fvv = (at(0, hh) - 2 * j.f + at(0, -hh)) / (hh * hh),
                   fuv = (at(hh, hh) - at(hh, -hh) - at(-hh, hh) + at(-hh, -hh)) / (4 * hh * hh);
      worst_jet = std::max({worst_jet, std::abs(j.fu - fu), std::abs(j.fv - fv),
                            std::abs(j.fuu - fuu), std::abs(j.fvv - fvv), std::abs(j.fuv - fuv)});
    }
    const double from_boundary = boundary_distance(poly, peak);
    std::printf(
        "%s: phi_0 peaks at (%.3f, %.3f), %.3f from the boundary = %.2f of the inradius "
        "%.3f; largest sample %.12f, least inside %.3g; jets vs differences %.3g; "
        "move vs phi_0 by %.3g\n",
        c.name.c_str(), peak.x, peak.y, from_boundary, from_boundary / inradius, inradius, best,
        least_inside, worst_jet, worst_move);
    EXPECT_GE(from_boundary, 0.75 * inradius) << c.name;
    EXPECT_LE(best, 1 + 1e-12) << c.name;
    EXPECT_GT(best, 0.99) << c.name;
    EXPECT_GT(least_inside, 0) << c.name;
    EXPECT_LT(worst_jet, 1e-4) << c.name;
    EXPECT_LT(worst_move, 1e-12) << c.name;
  }
}

}  // namespace
}  // namespace pl
