// Hostile input at the library level: the reading rules (duplicate keys, nesting, control
// characters, coordinate and span bounds, self-crossing faces, Catmull-Clark meshes OpenMesh
// would abort on), evaluation that stays exact at extreme scales, the finiteness check of every
// writer, and atomic writes' temporary files and messages.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cfloat>
#include <cmath>
#include <fstream>

#include "classic_test_util.hpp"
#include "core/base/data_error.hpp"
#include "core/geometry/differential_geometry.hpp"
#include "core/io/atomic_file.hpp"
#include "core/io/gbp_io.hpp"
#include "core/io/input_limits.hpp"
#include "core/io/json_node.hpp"
#include "core/io/scene_checks.hpp"
#include "core/io/scene_io.hpp"
#include "core/mesh/finite_check.hpp"
#include "core/patch/bezier_patch.hpp"
#include "core/patch/catmull_clark_patch.hpp"

namespace pl {
namespace {

// The DataError of parsing text as a scene (fails the test if it parses).
DataError scene_error(const std::string& text) {
  try {
    parse_scene(text, "s.json");
  } catch (const DataError& e) {
    return e;
  }
  ADD_FAILURE() << "accepted: " << text;
  return DataError("", "", "");
}

std::string bezier_scene(const std::string& points) {
  return R"({"patchlab": 1, "patches": [{"type": "bezier", "degree": [1, 1], "points": )" + points +
         "}]}";
}

TEST(HostileInput, DuplicateKeysAreRefusedWithTheirPath) {
  // The last one used to win, even after a value of the wrong type.
  const DataError e = scene_error(
      R"({"patchlab": 1, "patches": [{"type": 7, "type": "bezier", "degree": [1, 1],
          "points": [[0,0,0],[1,0,0],[0,1,0],[1,1,1]]}]})");
  EXPECT_EQ(e.where(), "patches[0].type");
  EXPECT_NE(e.message().find("duplicate key"), std::string::npos) << e.what();
  EXPECT_EQ(scene_error(R"({"patchlab": 1, "patchlab": 1})").where(), "patchlab");
}

TEST(HostileInput, NestingIsBounded) {
  std::string deep = R"({"patchlab": 1, "view": {"a": )";
  for (int i = 0; i < 200; ++i) deep += "[";
  for (int i = 0; i < 200; ++i) deep += "]";
  deep += "}}";
  const DataError e = scene_error(deep);
  EXPECT_NE(e.message().find("nesting deeper than 64"), std::string::npos) << e.what();
  EXPECT_EQ(e.where().rfind("view.a[0]", 0), 0u) << e.where();
}

TEST(HostileInput, AKeyWithANulIsPrintedWhole) {
  const DataError e = scene_error(std::string("{\"patchlab\": 1, \"ab\\u0000cd\": 2}"));
  const std::string what = e.what();
  EXPECT_EQ(what.find('\0'), std::string::npos);
  EXPECT_NE(what.find("ab\\u0000cd"), std::string::npos) << what;
  EXPECT_NE(what.find("unknown key"), std::string::npos) << what;
  EXPECT_EQ(printable(std::string("a\nb\x7f", 4)), "a\\u000ab\\u007f");
}

TEST(HostileInput, IntegersBeyondRangeAreNotWrapped) {
  const DataError e = scene_error(
      R"({"patchlab": 1, "patches": [{"type": "bezier", "degree": [18446744073709551615, 1],
          "points": []}]})");
  EXPECT_EQ(e.where(), "patches[0].degree[0]");
  EXPECT_NE(e.message().find("out of range"), std::string::npos) << e.what();
}

TEST(HostileInput, CoordinatesAreBoundedSoSquaredLengthsStayFinite) {
  // The bound: with |x| <= B every squared distance is at most 12 B^2.
  EXPECT_TRUE(std::isfinite(12 * kMaxCoordinate * kMaxCoordinate));
  const DataError e = scene_error(bezier_scene("[[0,0,0],[1,0,0],[0,1,0],[1,1,1e308]]"));
  EXPECT_EQ(e.where(), "patches[0].points[3][2]");
  EXPECT_NE(e.message().find("out of range"), std::string::npos) << e.what();
  // Just inside the bound is read (and evaluates: see the CLI tests).
  EXPECT_NO_THROW(parse_scene(bezier_scene("[[0,0,0],[1,0,0],[0,1,0],[1,1,3.7e153]]"), "s"));
  // The .gbp reader names the token.
  try {
    parse_gbp("3 1\n0 0 0\n1 0 0\n0 1 1e308\n1 1 0\n", "t.gbp");
    ADD_FAILURE();
  } catch (const DataError& g) {
    EXPECT_EQ(g.where(), "token 11");
    EXPECT_NE(g.message().find("out of range"), std::string::npos) << g.what();
  }
}

TEST(HostileInput, ASceneTooSmallForSquaredLengthsIsRefused) {
  const DataError e = scene_error(bezier_scene("[[0,0,0],[1e-160,0,0],[0,1e-160,0],[0,0,0]]"));
  EXPECT_EQ(e.where(), "patches[0]");
  EXPECT_NE(e.message().find("span only"), std::string::npos) << e.what();
  EXPECT_NO_THROW(
      parse_scene(bezier_scene("[[0,0,0],[1e-153,0,0],[0,1e-153,0],[0,0,1e-153]]"), "s"));
}

// A network of one face over the given loop of planar vertices, straight edges.
std::string loop_scene(const std::vector<Vec3>& v, const std::vector<int>& loop) {
  nlohmann::json net;
  for (const Vec3& p : v) net["vertices"].push_back({p.x, p.y, p.z});
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const Vec3 a = v[loop[i]], b = v[loop[(i + 1) % loop.size()]];
    const Vec3 h1 = a + (b - a) / 3.0, h2 = a + 2.0 * (b - a) / 3.0;
    net["edges"].push_back({{"v", {loop[i], loop[(i + 1) % loop.size()]}},
                            {"handles", {{h1.x, h1.y, h1.z}, {h2.x, h2.y, h2.z}}}});
  }
  net["faces"].push_back({{"loop", loop}});
  return nlohmann::json{{"patchlab", 1}, {"network", net}}.dump();
}

TEST(HostileInput, SelfCrossingFaceLoopsAreRefused) {
  std::vector<Vec3> pentagon;
  for (int i = 0; i < 5; ++i)
    pentagon.push_back({std::cos(2 * M_PI * i / 5), std::sin(2 * M_PI * i / 5), 0});
  const DataError star = scene_error(loop_scene(pentagon, {0, 2, 4, 1, 3}));
  EXPECT_EQ(star.where(), "network.faces[0].loop");
  EXPECT_NE(star.message().find("crosses itself"), std::string::npos) << star.what();
  // A bow tie: Newell's normal vanishes, the fitted plane still shows the crossing.
  const DataError bow =
      scene_error(loop_scene({{0, 0, 0}, {1, 1, 0}, {1, 0, 0}, {0, 1, 0}}, {0, 1, 2, 3}));
  EXPECT_EQ(bow.where(), "network.faces[0].loop");
  // The same pentagon in order, and a strongly bent but simple face, are read.
  EXPECT_NO_THROW(parse_scene(loop_scene(pentagon, {0, 1, 2, 3, 4}), "s"));
  std::vector<Vec3> saddle = {{0, 0, 0}, {1, 0, 1}, {1, 1, 0}, {0, 1, 1}};
  EXPECT_NO_THROW(parse_scene(loop_scene(saddle, {0, 1, 2, 3}), "s"));
}

TEST(HostileInput, FacesBeyondTheSideLimitAreRefusedBeforeAnyWork) {
  std::vector<Vec3> ring;
  std::vector<int> loop;
  for (int i = 0; i < kMaxFaceSides + 1; ++i) {
    ring.push_back({std::cos(2 * M_PI * i / 65), std::sin(2 * M_PI * i / 65), 0});
    loop.push_back(i);
  }
  const DataError e = scene_error(loop_scene(ring, loop));
  EXPECT_EQ(e.where(), "network.faces[0].loop");
  EXPECT_NE(e.message().find("at most 64 sides"), std::string::npos) << e.what();
}

std::string cc_scene(const std::string& faces, int vertices = 4) {
  nlohmann::json v = nlohmann::json::array();
  for (int i = 0; i < vertices; ++i)
    v.push_back({std::cos(2 * M_PI * i / vertices), std::sin(2 * M_PI * i / vertices), 0.0});
  return R"({"patchlab": 1, "patches": [{"type": "catmull-clark", "vertices": )" + v.dump() +
         R"(, "faces": )" + faces + "}]}";
}

TEST(HostileInput, CatmullClarkFacesWithARepeatedVertexAreRefusedNotAborted) {
  // OpenMesh's add_face asserted (boundary_prev.is_valid()) and aborted the process on these.
  for (const char* faces : {"[[0,0,1,2,3]]", "[[0,1,2,3,3]]", "[[0,1,0,2,3]]"}) {
    const DataError e = scene_error(cc_scene(faces));
    EXPECT_EQ(e.where(), "patches[0].faces[0]") << faces;
    EXPECT_NE(e.message().find("repeats vertex"), std::string::npos) << e.what();
  }
  // An edge used twice in one direction (a flipped neighbour): OpenMesh's "complex edge".
  const DataError flip = scene_error(cc_scene("[[0,1,2],[1,2,3]]"));
  EXPECT_EQ(flip.where(), "patches[0].faces[1]");
  EXPECT_NE(flip.message().find("used twice"), std::string::npos) << flip.what();
}

TEST(HostileInput, CatmullClarkFaceSizeIsBounded) {
  const int n = CatmullClarkLimit::kMaxValence + 1;
  std::string loop = "[[";
  for (int i = 0; i < n; ++i) {
    if (i) loop += ",";
    loop += std::to_string(i);
  }
  const DataError e = scene_error(cc_scene(loop + "]]", n));
  EXPECT_EQ(e.where(), "patches[0].faces[0]");
  EXPECT_NE(e.message().find("at most 256 vertices"), std::string::npos) << e.what();
}

TEST(HostileInput, CatmullClarkNGonPiecesAgreeWithOpenSubdivAndWithTheirBasis) {
  // A 40-gon: every patch point near its centre depends on all 40 vertices. The pieces place
  // those points once and sum 16 or 20 of them per sample; OpenSubdiv's limit stencils
  // (limit_point: its own patch lookup, basis and stencil accumulation) sum over the vertices.
  const int n = 40;
  std::vector<Vec3> v;
  std::vector<int> loop;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * M_PI * i / n;
    v.push_back({std::cos(a), std::sin(a), 0.2 * std::sin(3 * a)});
    loop.push_back(i);
  }
  const CatmullClarkPatch cc(v, {loop});
  const auto pieces = cc.surface_pieces();
  ASSERT_EQ(pieces.size(), std::size_t(n));
  double vs_osd = 0, interface = 0;
  for (int f : {0, 7, 39}) {
    for (const Vec2& x : test::random_domain_points(6, 500 + unsigned(f))) {
      const Vec3 a = pieces[f]->evaluate(x).p, b = cc.limit().limit_point(f, x, v);
      vs_osd = std::max(vs_osd, test::max_abs(a - b));
    }
    interface =
        std::max(interface, test::interface_mismatch(*pieces[f], test::random_domain_points(4, 9)));
  }
  std::printf("figure catmull_clark_40gon_vs_osd %.3e\nfigure catmull_clark_40gon_interface %.3e\n",
              vs_osd, interface);
  EXPECT_LT(vs_osd, 1e-12);
  EXPECT_LT(interface, 1e-12);
  // A moved vertex re-places the patch points: the piece then equals a fresh one.
  auto moved = pieces[3]->clone();
  moved->set_control_point(17, v[17] + Vec3(0.1, -0.3, 0.4));
  std::vector<Vec3> w = v;
  w[17] += Vec3(0.1, -0.3, 0.4);
  const auto fresh = CatmullClarkPatch(w, {loop}).surface_pieces();
  double drag = 0;
  for (const Vec2& x : test::random_domain_points(8, 11))
    drag = std::max(drag, test::max_abs(moved->evaluate(x).p - fresh[3]->evaluate(x).p));
  EXPECT_EQ(drag, 0.0);
}

// The jet of z = x y at (x, y) = (0.3, -0.2), scaled by s: K = -s^-2 / (1 + x^2 + y^2)^2.
SurfaceJet saddle_jet(double s) {
  const double x = 0.3, y = -0.2;
  SurfaceJet j;
  j.p = s * Vec3(x, y, x * y);
  j.su = s * Vec3(1, 0, y);
  j.sv = s * Vec3(0, 1, x);
  j.suv = s * Vec3(0, 0, 1);
  return j;
}

TEST(HostileInput, GeometryIsExactAtExtremeScales) {
  // |Su x Sv|^2 is a fourth power of the size: it overflows at 1e80 and underflows at 1e-80.
  const double x = 0.3, y = -0.2, W = 1 + x * x + y * y;
  for (double s : {1.0, 1e80, 1e150, 1e-80, 1e-150}) {
    const SurfaceGeometry g = differential_geometry(saddle_jet(s));
    ASSERT_EQ(g.status, GeometryStatus::Regular) << s;
    const Vec3 n = Vec3(-y, -x, 1) / std::sqrt(W);
    EXPECT_LT(test::max_abs(g.normal - n), 1e-15) << s;
    EXPECT_NEAR(g.gaussian * s * s, -1 / (W * W), 1e-14) << s;
    SurfaceGeometry many;
    const SurfaceJet j = saddle_jet(s);
    differential_geometry_many(std::span(&j, 1), std::span(&many, 1));
    EXPECT_EQ(many.normal, g.normal) << s;
  }
  SurfaceJet flat = saddle_jet(1e100);
  flat.sv = flat.su;  // truly singular stays singular
  EXPECT_EQ(differential_geometry(flat).status, GeometryStatus::Singular);
}

SurfaceMesh one_triangle(Vec3 normal, Vec3 corner) {
  SurfaceMesh m;
  m.name = "tri";
  m.positions = {corner, {1, 0, 0}, {0, 1, 0}};
  m.normals = {normal, {0, 0, 1}, {0, 0, 1}};
  m.params = {{0.25, 0.5}, {1, 0}, {0, 1}};
  m.gaussian = m.mean = m.kmin = m.kmax = {0, 0, 0};
  m.triangles = {{0, 1, 2}};
  return m;
}

TEST(HostileInput, TheFinitenessCheckNamesPatchAndParameter) {
  EXPECT_NO_THROW(check_finite(std::vector{one_triangle({0, 0, 1}, {0, 0, 0})}, "s.json"));
  for (const auto& [mesh, why] :
       {std::pair{one_triangle({0, 0, 0}, {0, 0, 0}), "no limit"},
        std::pair{one_triangle({0, 0, 1}, {NAN, 0, 0}), "not finite"},
        std::pair{one_triangle({0, 0, 1}, {INFINITY, 0, 0}), "not finite"}}) {
    try {
      check_finite(std::vector{mesh}, "s.json");
      ADD_FAILURE() << why;
    } catch (const DataError& e) {
      EXPECT_EQ(e.source(), "s.json");
      EXPECT_EQ(e.where(), "patch \"tri\" at (u, v) = (0.25, 0.5)");
      EXPECT_NE(e.message().find(why), std::string::npos) << e.what();
    }
  }
}

TEST(HostileInput, WriteErrorsNameTheTargetAndTheReason) {
  const std::filesystem::path target = "/no/such/dir/out.obj";
  try {
    write_file_atomically(target, "x");
    ADD_FAILURE();
  } catch (const DataError& e) {
    EXPECT_EQ(e.source(), target.string());
    EXPECT_EQ(e.message(), "cannot write: no such directory /no/such/dir");
  }
  const std::pair<int, const char*> reasons[] = {{ENOSPC, "disk full"},
                                                 {EACCES, "permission denied in directory /d"},
                                                 {EFBIG, "file too large"},
                                                 {EROFS, "read-only file system"}};
  for (const auto& [err, why] : reasons) {
    try {
      throw_write_error("/d/out.obj", err);
    } catch (const DataError& e) {
      EXPECT_EQ(e.source(), "/d/out.obj");
      EXPECT_NE(e.message().find(why), std::string::npos) << e.what();
    }
  }
}

TEST(HostileInput, TemporariesOfDeadWritersAreRemovedByTheNextWrite) {
  const auto dir =
      std::filesystem::temp_directory_path() / ("patchlab-tmp-" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  // A process id that is certainly gone: a child that has exited and been reaped.
  const pid_t child = fork();
  if (child == 0) _exit(0);
  waitpid(child, nullptr, 0);
  const auto dead = dir / (".out.obj.tmp" + std::to_string(child) + "-0");
  const auto dead_ext = dir / (".out.obj.tmp" + std::to_string(child) + "-3.obj");
  const auto live = dir / (".out.obj.tmp" + std::to_string(getpid()) + "-99");
  const auto other = dir / (".other.obj.tmp" + std::to_string(child) + "-0");
  for (const auto& p : {dead, dead_ext, live, other}) std::ofstream(p) << "half";
  write_file_atomically(dir / "out.obj", "whole\n");
  EXPECT_FALSE(std::filesystem::exists(dead));
  EXPECT_FALSE(std::filesystem::exists(dead_ext));
  EXPECT_TRUE(std::filesystem::exists(live));   // its writer may still be writing
  EXPECT_TRUE(std::filesystem::exists(other));  // another target's
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace pl
