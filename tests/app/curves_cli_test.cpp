// Free curves through the command line: every malformed curve gives exit 1 and one message naming
// the file and the JSON path; the OBJ polyline of every type equals de Boor's triangle (written
// here, on the curve's B-spline form) at the parameters the CLI contract names; analyze reports
// the curves and their joints.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cli_test_util.hpp"

namespace pl::test {
namespace {

std::string scene_with(const std::string& curve) {
  return R"({"patchlab": 1, "curves": [)" + curve + "]}";
}

struct BadCurve {
  const char* what;
  std::string curve;
  const char* path;  // the JSON path the message must name
};

std::vector<BadCurve> bad_curves() {
  const std::string pts4 = R"([[0,0,0],[1,1,0],[2,0,0],[3,1,0]])";
  return {
      {"decreasing knots",
       R"({"type":"bspline","degree":2,"points":)" + pts4 + R"(,"knots":[0,0,0,0.6,0.4,1,1]})",
       "curves[0].knots[4]"},
      {"knot of multiplicity p + 2",
       R"({"type":"bspline","degree":1,"points":)" + pts4 + R"(,"knots":[0,0,0.5,0.5,0.5,1]})",
       "curves[0].knots[4]"},
      {"zero weight", R"({"type":"nurbs","degree":2,"points":)" + pts4 + R"(,"weights":[1,0,1,1]})",
       "curves[0].weights[1]"},
      {"negative weight",
       R"({"type":"nurbs","degree":2,"points":)" + pts4 + R"(,"weights":[1,1,-2,1]})",
       "curves[0].weights[2]"},
      {"wrong weight count",
       R"({"type":"nurbs","degree":2,"points":)" + pts4 + R"(,"weights":[1,1,1]})",
       "curves[0].weights"},
      {"wrong knot count",
       R"({"type":"bspline","degree":2,"points":)" + pts4 + R"(,"knots":[0,0,0,1,1,1]})",
       "curves[0].knots"},
      {"too few points for the degree",
       R"({"type":"bspline","degree":3,"points":[[0,0,0],[1,0,0],[1,1,0]]})", "curves[0].points"},
      {"interpolating with three points",
       R"({"type":"interpolating","points":[[0,0,0],[1,0,0],[1,1,0]]})", "curves[0].points"},
      {"hermite without a tangent",
       R"({"type":"hermite","points":[[0,0,0],[1,0,0]],"tangents":[[1,0,0]]})",
       "curves[0].tangents"},
      {"bezier with one point", R"({"type":"bezier","points":[[0,0,0]]})", "curves[0].points"},
      {"degree 0", R"({"type":"bspline","degree":0,"points":)" + pts4 + "}", "curves[0].degree"},
      {"non-finite coordinate", R"({"type":"bezier","points":[[0,0,0],[1e999,0,0]]})",
       "curves[0].points[1][0]"},
      {"non-finite knot",
       R"({"type":"bspline","degree":2,"points":)" + pts4 + R"(,"knots":[0,0,0,0.5,1,1,1e999]})",
       "curves[0].knots[6]"},
      {"non-finite weight",
       R"({"type":"nurbs","degree":2,"points":)" + pts4 + R"(,"weights":[1,1,-1e999,1]})",
       "curves[0].weights[2]"},
      {"empty range",
       R"({"type":"bspline","degree":1,"points":[[0,0,0],[1,0,0]],"knots":[0,0.5,0.5,1]})",
       "curves[0].knots"},
      {"unknown type", R"({"type":"spiral","points":[[0,0,0],[1,0,0]]})", "curves[0].type"},
      {"unknown key", R"({"type":"bezier","points":[[0,0,0],[1,0,0]],"knots":[0,1]})",
       "curves[0].knots"},
      {"weights on a bspline",
       R"({"type":"bspline","degree":2,"points":)" + pts4 + R"(,"weights":[1,1,1,1]})",
       "curves[0].weights"},
      {"knot out of range",
       R"({"type":"bspline","degree":1,"points":[[0,0,0],[1,1,0]],"knots":[-1e308,-1e308,1e308,1e308]})",
       "curves[0].knots[0]"},
      {"numbers that overflow when evaluated",
       R"({"type":"nurbs","degree":2,"points":[[0,0,0],[1e150,1,0],[2,0,0]],"weights":[1,1e300,1]})",
       "curves[0]"},
      {"all points in one place", R"({"type":"bezier","points":[[1,1,1],[1,1,1]]})",
       "curves[0].points"},
  };
}

TEST(CurvesCli, EveryMalformedCurveIsExitOneWithTheFileAndPath) {
  TempDir dir;
  for (const BadCurve& b : bad_curves()) {
    const auto file = dir.file("bad.json", scene_with(b.curve));
    for (const char* command : {"analyze", "export"}) {
      std::vector<std::string> args{command, file.string()};
      if (std::string(command) == "export")
        args.insert(args.end(), {"-o", (dir / "o.obj").string()});
      const CliResult r = cli(args);
      EXPECT_EQ(r.code, 1) << b.what << ": " << r.err;
      EXPECT_NE(r.err.find(file.string() + ": " + b.path + ":"), std::string::npos)
          << b.what << ": " << r.err;
      // One message: one line.
      EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << b.what << ": " << r.err;
    }
  }
}

// --- independent evaluation -------------------------------------------------------------------

struct Spline {
  int p;
  std::vector<double> U;
  std::vector<glm::dvec4> P;  // homogeneous
};

glm::dvec3 de_boor(const Spline& s, double t) {
  const int p = s.p;
  int k = p;
  while (k + 1 < static_cast<int>(s.P.size()) && s.U[k + 1] <= t) ++k;
  std::vector<glm::dvec4> d(s.P.begin() + (k - p), s.P.begin() + k + 1);
  for (int r = 1; r <= p; ++r)
    for (int j = p; j >= r; --j) {
      const int i = j + k - p;
      const double a = (t - s.U[i]) / (s.U[i + p - r + 1] - s.U[i]);
      d[j] = (1 - a) * d[j - 1] + a * d[j];
    }
  return glm::dvec3(d[p]) / d[p].w;
}

Spline bezier_spline(const std::vector<glm::dvec3>& b) {
  Spline s{static_cast<int>(b.size()) - 1, {}, {}};
  s.U.assign(b.size(), 0.0);
  s.U.insert(s.U.end(), b.size(), 1.0);
  for (const auto& q : b) s.P.emplace_back(q, 1.0);
  return s;
}

// Reads every "v" of the object named `name` in an OBJ file, and checks its "l" line runs
// through them in order.
std::vector<glm::dvec3> obj_polyline(const std::string& obj, const std::string& name) {
  std::istringstream in(obj);
  std::string line;
  bool inside = false;
  std::size_t seen = 0, first = 0;
  std::vector<glm::dvec3> pts;
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    std::string tag;
    ls >> tag;
    if (tag == "o") {
      std::string n;
      ls >> n;
      inside = n == name;
      if (inside) first = seen + 1;
    } else if (tag == "v") {
      ++seen;
      if (inside) {
        glm::dvec3 v;
        ls >> v.x >> v.y >> v.z;
        pts.push_back(v);
      }
    } else if (tag == "l" && inside) {
      std::size_t idx, k = 0;
      while (ls >> idx) EXPECT_EQ(idx, first + k++);
      EXPECT_EQ(k, pts.size());
    }
  }
  return pts;
}

TEST(CurvesCli, ObjPolylineOfEveryTypeEqualsDeBoor) {
  const double h = std::sqrt(0.5);
  // Bézier forms of the interpolating cubic and the Hermite curve written here from their
  // definitions (monomial coefficients by M_I and the Hermite basis), independent of the code.
  const glm::dvec3 i0(0, 0, 0), i1(1, 2, 0.5), i2(2.5, -0.5, 1), i3(3, 1, -0.25);
  // Monomial coefficients of the cubic through i_k at k/3 (Lagrange, expanded).
  const glm::dvec3 a0 = i0, a1 = -5.5 * i0 + 9.0 * i1 - 4.5 * i2 + i3,
                   a2 = 9.0 * i0 - 22.5 * i1 + 18.0 * i2 - 4.5 * i3,
                   a3 = -4.5 * i0 + 13.5 * i1 - 13.5 * i2 + 4.5 * i3;
  const std::vector<glm::dvec3> interp_bezier{a0, a0 + a1 / 3.0, a0 + 2.0 * a1 / 3.0 + a2 / 3.0,
                                              a0 + a1 + a2 + a3};
  const glm::dvec3 h0(0, 0, 0), h1(2, 1, 0), d0(3, 0, 1), d1(0, -4, 0.5);
  const std::vector<glm::dvec3> herm_bezier{h0, h0 + d0 / 3.0, h1 - d1 / 3.0, h1};
  Spline bs{3, {-0.5, -0.2, 0, 0.1, 0.3, 0.3, 0.7, 0.9, 1.2, 1.4, 1.5}, {}};
  const std::vector<glm::dvec3> bpts{{0, 0, 0},  {1, 2, 0.5}, {2, -1, 0}, {3, 1, 1},
                                     {4, 0, -1}, {5, 2, 0},   {6, 1, 0.5}};
  const std::vector<double> w{1, 0.5, 2, 1.5, 0.7, 1, 3};
  Spline nu = bs;
  for (std::size_t i = 0; i < bpts.size(); ++i) {
    bs.P.emplace_back(bpts[i], 1.0);
    nu.P.emplace_back(w[i] * bpts[i], w[i]);
  }
  Spline circle{2, {0, 0, 0, .25, .25, .5, .5, .75, .75, 1, 1, 1}, {}};
  const double cx[9] = {1, 1, 0, -1, -1, -1, 0, 1, 1}, cy[9] = {0, 1, 1, 1, 0, -1, -1, -1, 0};
  for (int i = 0; i < 9; ++i) {
    const double wi = i % 2 ? h : 1.0;
    circle.P.emplace_back(wi * glm::dvec3(3 * cx[i], 3 * cy[i], 1), wi);
  }
  const std::vector<glm::dvec3> bez{{0, 0, 0}, {1, 2, 0}, {2, -1, 1}, {3, 0.5, 0}, {4, 1, -1}};

  nlohmann::json curves = nlohmann::json::array();
  curves.push_back({{"type", "bezier"},
                    {"name", "bez"},
                    {"points", {{0, 0, 0}, {1, 2, 0}, {2, -1, 1}, {3, 0.5, 0}, {4, 1, -1}}}});
  curves.push_back({{"type", "interpolating"},
                    {"name", "interp"},
                    {"points", {{0, 0, 0}, {1, 2, 0.5}, {2.5, -0.5, 1}, {3, 1, -0.25}}}});
  curves.push_back({{"type", "hermite"},
                    {"name", "herm"},
                    {"points", {{0, 0, 0}, {2, 1, 0}}},
                    {"tangents", {{3, 0, 1}, {0, -4, 0.5}}}});
  nlohmann::json jb{{"type", "bspline"}, {"name", "bs"}, {"degree", 3}, {"knots", bs.U}};
  for (const auto& q : bpts) jb["points"].push_back({q.x, q.y, q.z});
  curves.push_back(jb);
  nlohmann::json jn = jb;
  jn["type"] = "nurbs", jn["name"] = "nu", jn["weights"] = w;
  curves.push_back(jn);
  nlohmann::json jc{{"type", "nurbs"}, {"degree", 2}, {"knots", circle.U}};
  for (int i = 0; i < 9; ++i) {
    jc["points"].push_back({3 * cx[i], 3 * cy[i], 1});
    jc["weights"].push_back(i % 2 ? h : 1.0);
  }
  curves.push_back(jc);  // unnamed: curve5

  TempDir dir;
  const auto file =
      dir.file("curves.json", nlohmann::json{{"patchlab", 1}, {"curves", curves}}.dump());
  const int N = 7;
  const CliResult r = cli(
      {"export", file.string(), "-o", (dir / "c.obj").string(), "--density", std::to_string(N)});
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string obj = slurp(dir / "c.obj");

  struct Expect {
    const char* name;
    Spline s;
    double a, b;
    std::vector<double> breaks;  // span ends inside (a, b)
  };
  const std::vector<Expect> expects{
      {"bez", bezier_spline(bez), 0, 1, {}},
      {"interp", bezier_spline(interp_bezier), 0, 1, {}},
      {"herm", bezier_spline(herm_bezier), 0, 1, {}},
      {"bs", bs, 0.1, 0.9, {0.3, 0.7}},
      {"nu", nu, 0.1, 0.9, {0.3, 0.7}},
      {"curve5", circle, 0, 1, {0.25, 0.5, 0.75}},
  };
  for (const Expect& e : expects) {
    std::vector<double> ends{e.a};
    ends.insert(ends.end(), e.breaks.begin(), e.breaks.end());
    ends.push_back(e.b);
    std::vector<double> ts{e.a};
    for (std::size_t s = 0; s + 1 < ends.size(); ++s)
      for (int k = 1; k <= N; ++k)
        ts.push_back(k == N ? ends[s + 1] : ends[s] + (ends[s + 1] - ends[s]) * (double(k) / N));
    const auto pts = obj_polyline(obj, e.name);
    ASSERT_EQ(pts.size(), ts.size()) << e.name;
    double size = 0;
    for (const auto& q : e.s.P) size = std::max(size, glm::length(glm::dvec3(q) / q.w));
    for (std::size_t i = 0; i < ts.size(); ++i)
      EXPECT_LE(glm::length(pts[i] - de_boor(e.s, ts[i])), 1e-13 * size)
          << e.name << " t=" << ts[i];
  }
  // Other formats leave the curves out, and say nothing wrong about them.
  EXPECT_EQ(cli({"export", file.string(), "-o", (dir / "c.ply").string()}).code, 0);
}

TEST(CurvesCli, AnalyzeReportsCurvesAndJoints) {
  const double r = 1.75, h = std::sqrt(0.5);
  nlohmann::json circle{{"type", "nurbs"},
                        {"name", "ring"},
                        {"degree", 2},
                        {"knots", {0, 0, 0, .25, .25, .5, .5, .75, .75, 1, 1, 1}}};
  const double cx[9] = {1, 1, 0, -1, -1, -1, 0, 1, 1}, cy[9] = {0, 1, 1, 1, 0, -1, -1, -1, 0};
  for (int i = 0; i < 9; ++i) {
    circle["points"].push_back({r * cx[i] + 5, r * cy[i], 0});
    circle["weights"].push_back(i % 2 ? h : 1.0);
  }
  // G1, not G2: both tangents along +x at (1, 0, 0).
  const nlohmann::json a{{"type", "bezier"},
                         {"points", {{0, 1, 0}, {0.3, 0.2, 0}, {0.6, 0, 0}, {1, 0, 0}}}};
  const nlohmann::json b{{"type", "bezier"},
                         {"points", {{1, 0, 0}, {1.5, 0, 0}, {1.7, 0.6, 0}, {2, 1, 0}}}};
  TempDir dir;
  const auto file =
      dir.file("s.json", nlohmann::json{{"patchlab", 1}, {"curves", {circle, a, b}}}.dump());
  const CliResult res = cli({"analyze", file.string(), "--json"});
  ASSERT_EQ(res.code, 0) << res.err;
  const auto j = nlohmann::json::parse(res.out);
  ASSERT_EQ(j["curves"].size(), 3u);
  const auto& c0 = j["curves"][0];
  EXPECT_EQ(c0["name"], "ring");
  EXPECT_EQ(c0["type"], "nurbs");
  EXPECT_EQ(c0["degree"], 2);
  EXPECT_EQ(c0["spans"], 4);
  EXPECT_NEAR(c0["length"].get<double>(), 2 * M_PI * r, 1e-9 * 2 * M_PI * r);
  EXPECT_NEAR(c0["curvature"][0].get<double>(), 1 / r, 1e-12 / r);
  EXPECT_NEAR(c0["curvature"][1].get<double>(), 1 / r, 1e-12 / r);
  EXPECT_EQ(c0["inflections"], 0);
  EXPECT_EQ(c0["nonfinite_samples"], 0);
  EXPECT_EQ(j["curves"][1]["name"], "curve1");
  // Joints: the circle closes on itself; curve1's end meets curve2's start.
  ASSERT_EQ(j["joints"].size(), 2u);
  EXPECT_EQ(j["joints"][0]["curves"], nlohmann::json({0, 0}));
  EXPECT_LT(j["joints"][0]["tangent_angle_deg"].get<double>(), 1e-9);
  EXPECT_LT(j["joints"][0]["curvature_jump"].get<double>(), 1e-9);
  EXPECT_EQ(j["joints"][1]["curves"], nlohmann::json({1, 2}));
  EXPECT_LT(j["joints"][1]["tangent_angle_deg"].get<double>(), 1e-9);
  EXPECT_GT(j["joints"][1]["curvature_jump"].get<double>(), 0.5);
}

TEST(CurvesCli, CurvesSurviveConvertRoundTrip) {
  TempDir dir;
  const auto file = dir.file(
      "s.json",
      scene_with(
          R"({"type":"nurbs","name":"n","degree":2,"points":[[0,0,0],[1,1,0],[2,0,0],[3,1,0]],)"
          R"("knots":[0,0,0,0.30000000000000004,1,1,1],"weights":[1,0.1,2,1]},)"
          R"({"type":"hermite","points":[[0,0,0],[1,0,0]],"tangents":[[0,1,0],[1,0,0]]},)"
          R"({"type":"bspline","degree":1,"points":[[0,0,0],[1,0,0]]})"));
  const auto out = dir / "t.json";
  ASSERT_EQ(cli({"convert", file.string(), "-o", out.string()}).code, 0);
  const auto a = nlohmann::json::parse(slurp(file)), b = nlohmann::json::parse(slurp(out));
  EXPECT_EQ(b["curves"][0], a["curves"][0]);
  EXPECT_EQ(b["curves"][1], a["curves"][1]);
  // Knots left out are written as the clamped uniform vector they mean.
  EXPECT_EQ(b["curves"][2]["knots"], nlohmann::json({0, 0, 1, 1}));
}

}  // namespace
}  // namespace pl::test
