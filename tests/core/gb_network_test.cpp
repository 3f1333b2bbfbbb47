// GB faces in curve networks, next to Gregory faces: every face interpolates its edges and meets
// its neighbours with the same tangent plane (the Chiyokura–Kimura ribbons are shared). Checked
// twice: directly (faces filled here, normals compared sample by sample along every shared edge
// from each face's own evaluation) and through evaluate_scene + analyze_scene.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "core/analysis/scene_analysis.hpp"
#include "core/base/data_error.hpp"
#include "core/domain/tessellation_cache.hpp"
#include "core/eval/scene_surfaces.hpp"
#include "core/io/scene_io.hpp"
#include "core/network/face_ribbons.hpp"
#include "core/network/gb_face.hpp"
#include "core/network/gregory_face.hpp"

namespace pl {
namespace {

Scene load(const std::string& name) {
  const std::string path = std::string(PATCHLAB_SOURCE_DIR) + "/assets/" + name;
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return parse_scene(ss.str(), path);
}

double angle_between(Vec3 a, Vec3 b) {
  return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b)) * 180 / M_PI;
}

struct Figures {
  double max_deviation = 0, max_angle = 0;
  int gb_faces = 0, gregory_faces = 0;
};

// Fills every face here (GB for n >= 5 and wherever forced, Gregory otherwise) and compares the
// faces' normals along each shared edge at the edge parameters k / N, evaluating each face at
// its own domain point of that edge parameter.
Figures direct(const Scene& scene, bool all_gb) {
  const Network& net = *scene.network;
  const NetworkTopology topo = validate_network(net, "test");
  std::vector<ProjectedVertex> projected;
  const std::vector<FaceRibbons> ribbons = build_face_ribbons(net, topo, projected);
  std::vector<std::unique_ptr<Patch>> patches;
  Figures fig;
  for (std::size_t f = 0; f < net.faces.size(); ++f) {
    const bool gb = all_gb || net.faces[f].loop.size() > 4;
    patches.push_back(gb ? std::unique_ptr<Patch>(gb_face_patch(ribbons[f]))
                         : gregory_face_patch(ribbons[f]));
    ++(gb ? fig.gb_faces : fig.gregory_faces);
  }
  const int N = 32;
  for (std::size_t e = 0; e < topo.edge_faces.size(); ++e) {
    const BezierCurve curve = net.edge_curve(int(e));
    double scale = 0;
    for (const Vec3& p : curve.control_points()) scale = std::max(scale, glm::length(p));
    Vec3 normal[2][N + 1];
    const auto& uses = topo.edge_faces[e];
    for (std::size_t u = 0; u < uses.size(); ++u) {
      const Patch& p = *patches[uses[u].face];
      const bool reversed = topo.face_sides[uses[u].face][uses[u].side].reversed;
      for (int k = 0; k <= N; ++k) {
        const double t = double(k) / N;  // edge parameter
        const double side_t = reversed ? 1 - t : t;
        const SurfaceJet s = p.evaluate(p.domain().side_point(uses[u].side, side_t));
        fig.max_deviation = std::max(fig.max_deviation, glm::length(s.p - curve.point(t)) / scale);
        normal[u][k] = glm::cross(s.su, s.sv);
      }
    }
    if (uses.size() == 2)
      for (int k = 0; k <= N; ++k)
        fig.max_angle = std::max(fig.max_angle, angle_between(normal[0][k], normal[1][k]));
  }
  return fig;
}

void expect_direct(const std::string& file, bool all_gb) {
  const Figures fig = direct(load(file), all_gb);
  std::printf(
      "%s (%s): %d GB + %d Gregory faces, max edge deviation %.3g (relative), max normal "
      "angle across shared edges %.3g deg\n",
      file.c_str(), all_gb ? "all GB" : "auto", fig.gb_faces, fig.gregory_faces, fig.max_deviation,
      fig.max_angle);
  EXPECT_LT(fig.max_deviation, 1e-12) << file;
  EXPECT_LT(fig.max_angle, 1e-6) << file;
}

TEST(GBNetwork, PentagonAndHexagonAmongQuadsAndTrianglesAreG1) {
  expect_direct("gb-hole-filling.json", false);
  expect_direct("gb-hole-filling.json", true);  // triangles and quads as GB faces too
}

TEST(GBNetwork, ConcaveLFaceIsG1WithItsNeighbours) {
  expect_direct("gb-concave-l.json", false);
  expect_direct("gb-concave-l.json", true);
  const Scene s = load("gb-concave-l.json");
  const NetworkTopology topo = validate_network(*s.network, "test");
  std::vector<ProjectedVertex> projected;
  const auto ribbons = build_face_ribbons(*s.network, topo, projected);
  GBDomainKind kind{};
  const auto patch = gb_face_patch(ribbons[0], &kind);
  EXPECT_EQ(kind, GBDomainKind::AngleLength);
  // One reflex corner (the end of face side 2, at vertex 3), the rest convex.
  const auto turning = face_turning_angles(ribbons[0]);
  for (std::size_t i = 0; i < turning.size(); ++i) EXPECT_EQ(turning[i] < 0, i == 2) << i;
}

// Each GB face against its own cubic ribbons (the data it is built from: the network's, turned
// into the face at reflex corners), corners included:
// position along every side and Su x Sv against tangent x 3 (inner - boundary).
TEST(GBNetwork, FacesInterpolateTheirRibbonsWithTheirTangentPlanes) {
  for (const char* file : {"gb-hole-filling.json", "gb-concave-l.json"}) {
    const Scene s = load(file);
    const NetworkTopology topo = validate_network(*s.network, "test");
    std::vector<ProjectedVertex> projected;
    const auto ribbons = build_face_ribbons(*s.network, topo, projected);
    double dev = 0, angle = 0;
    for (const FaceRibbons& network_ribbons : ribbons) {
      const auto patch = gb_face_patch(network_ribbons);
      const FaceRibbons fr = orient_reflex_corners(network_ribbons);
      for (std::size_t i = 0; i < fr.sides.size(); ++i) {
        const CubicRibbon& r = fr.sides[i];
        const BezierCurve edge(std::vector<Vec3>(r.boundary.begin(), r.boundary.end()));
        std::vector<Vec3> rows;
        for (int j = 0; j < 4; ++j) rows.push_back(3.0 * (r.inner[j] - r.boundary[j]));
        const BezierCurve cross(rows);
        double scale = 0;
        for (const Vec3& p : r.boundary) scale = std::max(scale, glm::length(p));
        for (int k = 0; k <= 32; ++k) {
          const double t = k / 32.0;
          const SurfaceJet sj = patch->evaluate(patch->domain().side_point(int(i), t));
          const CurvePoint c = edge.evaluate(t);
          dev = std::max(dev, glm::length(sj.p - c.p) / scale);
          angle = std::max(
              angle, angle_between(glm::cross(sj.su, sj.sv), glm::cross(c.d1, cross.point(t))));
        }
      }
    }
    std::printf("%s: GB faces vs their ribbons: deviation %.3g (relative), normal angle %.3g deg\n",
                file, dev, angle);
    EXPECT_LT(dev, 1e-12) << file;
    EXPECT_LT(angle, 1e-6) << file;
  }
}

// The scene path: fill_network (GB faces for n >= 5) + evaluate_scene + analyze_scene.
void expect_analysis(const std::string& file, std::optional<FaceScheme> scheme) {
  const Scene scene = load(file);
  TessellationCache cache;
  const SceneSurfaces ss = evaluate_scene(scene, 24, scheme, cache, file);
  const SceneReport r = analyze_scene(scene, ss);
  double dev = 0, angle = 0, gap = 0;
  std::size_t nonfinite = 0;
  for (const PatchReport& p : r.patches) {
    dev = std::max(dev, p.max_boundary_deviation);
    nonfinite += p.nonfinite_samples;
  }
  for (const EdgeReport& e : r.edges) {
    angle = std::max(angle, e.max_normal_angle_deg);
    gap = std::max(gap, e.max_gap);
  }
  std::printf(
      "%s analyze: %zu patches, %zu shared edges, boundary deviation %.3g, gap %.3g, "
      "normal angle %.3g deg\n",
      file.c_str(), r.patches.size(), r.edges.size(), dev, gap, angle);
  EXPECT_EQ(nonfinite, 0u);
  EXPECT_LT(dev, 1e-12);
  EXPECT_LT(gap, 1e-12);
  EXPECT_LT(angle, 1e-6);
  EXPECT_GT(r.edges.size(), 0u);
}

TEST(GBNetwork, SceneAnalysis) {
  expect_analysis("gb-hole-filling.json", std::nullopt);
  expect_analysis("gb-hole-filling.json", FaceScheme::GB);
  expect_analysis("gb-concave-l.json", std::nullopt);
}

// One n-gon face (n = 3..12, a wavy rim) filled as GB: finite everywhere, boundary interpolated.
TEST(GBNetwork, SingleFacesForEverySideCountAreFinite) {
  for (int n = 3; n <= 12; ++n) {
    Scene scene;
    Network net;
    for (int i = 0; i < n; ++i) {
      const double a = 2 * M_PI * i / n;
      net.vertices.push_back({std::cos(a), std::sin(a), 0.2 * std::cos(2 * a)});
    }
    for (int i = 0; i < n; ++i) {
      const Vec3 p = net.vertices[i], q = net.vertices[(i + 1) % n];
      NetworkEdge e;
      e.v = {i, (i + 1) % n};
      e.handles = {p + (q - p) / 3.0 + Vec3(0, 0, 0.1), p + 2.0 * (q - p) / 3.0 - Vec3(0, 0, 0.05)};
      net.edges.push_back(e);
    }
    NetworkFace f;
    for (int i = 0; i < n; ++i) f.loop.push_back(i);
    net.faces.push_back(f);
    scene.network = net;
    TessellationCache cache;
    const SceneSurfaces ss = evaluate_scene(scene, 16, FaceScheme::GB, cache, "ngon");
    const SceneReport r = analyze_scene(scene, ss);
    ASSERT_EQ(r.patches.size(), 1u);
    EXPECT_EQ(r.patches[0].type, "gb-ribbons");
    EXPECT_EQ(r.patches[0].nonfinite_samples, 0u) << n;
    EXPECT_LT(r.patches[0].max_boundary_deviation, 1e-12) << n;
  }
}

// One network face over a planar polygon lifted to z = c x y, with straight cubic edges.
Scene lifted_face(const std::vector<Vec2>& polygon, double c) {
  Scene scene;
  Network net;
  const int n = static_cast<int>(polygon.size());
  for (const Vec2& p : polygon) net.vertices.push_back({p.x, p.y, c * p.x * p.y});
  NetworkFace f;
  for (int i = 0; i < n; ++i) {
    const Vec3 p = net.vertices[i], q = net.vertices[(i + 1) % n];
    NetworkEdge e;
    e.v = {i, (i + 1) % n};
    e.handles = {p + (q - p) / 3.0, p + 2.0 * (q - p) / 3.0};
    net.edges.push_back(e);
    f.loop.push_back(i);
  }
  f.scheme = FaceScheme::GB;
  net.faces.push_back(f);
  scene.network = net;
  return scene;
}

// A rectangular notch (0.5 wide, 0.3 deep in a unit square) and a deep U: mean value
// coordinates of the vertices behind the notch's walls turn negative, so lambda_{i-1} +
// lambda_i vanishes inside (and, for the notch's floor, grows from the far sides with no
// slope): cubic ribbons with two layers would have poles there. Those sides get a third layer
// (exact: same edge, same cross-boundary derivative); the face fills, interpolates its ribbons
// with their tangent planes, and its curvature stays that of a gently lifted plane.
TEST(GBNetwork, NotchAndUFacesFillWithoutPoles) {
  const std::vector<Vec2> notch = {{0, 0},      {1, 0},      {1, 1},    {0.75, 1},
                                   {0.75, 0.7}, {0.25, 0.7}, {0.25, 1}, {0, 1}};
  const std::vector<Vec2> u = {{0, 0}, {3, 0}, {3, 2}, {2, 2}, {2, 0.8}, {1, 0.8}, {1, 2}, {0, 2}};
  for (const auto& [poly, name] : {std::pair{notch, "notch"}, std::pair{u, "U"}}) {
    const Scene scene = lifted_face(poly, 0.1);
    const NetworkTopology topo = validate_network(*scene.network, name);
    std::vector<ProjectedVertex> projected;
    const auto ribbons = build_face_ribbons(*scene.network, topo, projected);
    const auto patch = gb_face_patch(ribbons[0]);
    const auto poles = GBRibbonPatch::sides_without_positive_pair(patch->polygon());
    EXPECT_FALSE(poles.empty()) << name;  // mean value coordinates do fail on these domains
    for (int i = 0; i < patch->sides(); ++i) {
      const bool pole = std::find(poles.begin(), poles.end(), i) != poles.end();
      EXPECT_EQ(patch->layers(i), pole ? 3 : 2) << name << " side " << i;
    }
    // Along every side: the edge, and the normal of the (reflex-corner oriented) ribbon.
    const FaceRibbons fr = orient_reflex_corners(ribbons[0]);
    double dev = 0, angle = 0;
    for (std::size_t i = 0; i < fr.sides.size(); ++i) {
      const CubicRibbon& r = fr.sides[i];
      const BezierCurve edge(std::vector<Vec3>(r.boundary.begin(), r.boundary.end()));
      std::vector<Vec3> rows;
      for (int j = 0; j < 4; ++j) rows.push_back(3.0 * (r.inner[j] - r.boundary[j]));
      const BezierCurve cross(rows);
      for (int k = 1; k < 32; ++k) {
        const double t = k / 32.0;
        const SurfaceJet sj = patch->evaluate(patch->domain().side_point(int(i), t));
        const CurvePoint c = edge.evaluate(t);
        dev = std::max(dev, glm::length(sj.p - c.p));
        angle = std::max(angle,
                         angle_between(glm::cross(sj.su, sj.sv), glm::cross(c.d1, cross.point(t))));
      }
    }
    TessellationCache cache;
    const SceneSurfaces ss = evaluate_scene(scene, 32, std::nullopt, cache, name);
    const SceneReport r = analyze_scene(scene, ss);
    ASSERT_EQ(r.patches.size(), 1u);
    const PatchReport& p = r.patches[0];
    const double h = std::max(std::fabs(p.mean[0]), std::fabs(p.mean[1]));
    std::printf("%s face: deviation %.3g, normal angle %.3g deg, |H| <= %.3g, %zu pole sides\n",
                name, dev, angle, h, poles.size());
    EXPECT_LT(dev, 1e-12) << name;
    EXPECT_LT(angle, 1e-6) << name;
    EXPECT_EQ(p.nonfinite_samples, 0u) << name;
    EXPECT_EQ(p.singular_samples, 0u) << name;
    // Measured 1.1 (notch) and 0.8 (U); a two-layer ribbon left with a near pole gave 190.
    EXPECT_LT(h, 2.0) << name;
  }
}

// A comb with three deep teeth: along the teeth's walls the coordinates of the vertices hidden
// behind the other teeth cancel the growth of the distance parameter, so no ribbon has a
// cross-boundary direction there. Filling it is a DataError naming the face and the reason,
// never non-finite samples or a folded surface.
TEST(GBNetwork, UnfillableConcaveFaceIsADataErrorNamingTheFace) {
  const std::vector<Vec2> comb = {
      {0, 0},     {4, 0},     {4, 2},   {3.6, 2}, {3.6, 0.5}, {3.2, 0.5}, {3.2, 2}, {2.2, 2},
      {2.2, 0.5}, {1.8, 0.5}, {1.8, 2}, {0.8, 2}, {0.8, 0.5}, {0.4, 0.5}, {0.4, 2}, {0, 2}};
  TessellationCache cache;
  try {
    evaluate_scene(lifted_face(comb, 0.05), 8, std::nullopt, cache, "comb.json");
    FAIL() << "expected a DataError";
  } catch (const DataError& e) {
    EXPECT_EQ(e.source(), "comb.json");
    EXPECT_EQ(e.where(), "network.faces[0]");
    EXPECT_NE(e.message().find("does not grow into the domain"), std::string::npos) << e.what();
    std::printf("%s\n", e.what());
  }
}

}  // namespace
}  // namespace pl
