// `patchlab export`: OBJ/PLY normals are the exact ones (checked against the closed form of the
// surface, independent of the evaluator) and orientations agree.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "cli_test_util.hpp"

namespace pl::test {
namespace {

// Bicubic Bézier patch representing the paraboloid-free saddle z = x y exactly: a bilinear patch
// degree-elevated to bicubic. P_ij = (i/3, j/3, (i/3)(j/3)) on [0,1]^2.
std::string saddle_scene() {
  std::string pts;
  for (int i = 0; i <= 3; ++i)
    for (int j = 0; j <= 3; ++j) {
      char buf[128];
      std::snprintf(buf, sizeof buf, "%s[%.17g,%.17g,%.17g]", pts.empty() ? "" : ",", i / 3.0,
                    j / 3.0, (i / 3.0) * (j / 3.0));
      pts += buf;
    }
  return R"({"patchlab":1,"patches":[{"type":"bezier","name":"saddle","degree":[3,3],"points":[)" +
         pts + "]}]}";
}

TEST(Export, ObjNormalsAreExactAndTrianglesAgreeWithThem) {
  TempDir dir;
  const auto scene = dir.file("saddle.json", saddle_scene());
  const auto obj = dir / "saddle.obj";
  const CliResult r = cli({"export", scene.string(), "-o", obj.string(), "--density", "12"});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  std::istringstream in(slurp(obj));
  std::string tag;
  std::vector<std::array<double, 3>> v, vn;
  std::vector<std::array<int, 3>> f;
  int objects = 0;
  for (std::string line; std::getline(in, line);) {
    std::istringstream ls(line);
    ls >> tag;
    if (tag == "o") {
      ++objects;
      std::string name;
      ls >> name;
      EXPECT_EQ(name, "saddle");
    } else if (tag == "v" || tag == "vn") {
      std::array<double, 3> a;
      ls >> a[0] >> a[1] >> a[2];
      (tag == "v" ? v : vn).push_back(a);
    } else if (tag == "f") {
      std::array<int, 3> t;
      for (int k = 0; k < 3; ++k) {
        std::string c;
        ls >> c;
        t[k] = std::stoi(c.substr(0, c.find('/')));
        EXPECT_EQ(c.substr(c.find("//") + 2), c.substr(0, c.find('/')));  // a//a
      }
      f.push_back(t);
    }
  }
  EXPECT_EQ(objects, 1);
  ASSERT_EQ(v.size(), 13u * 13u);
  ASSERT_EQ(vn.size(), v.size());
  double worst = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const double x = v[i][0], y = v[i][1];
    EXPECT_NEAR(v[i][2], x * y, 1e-15);
    const double w = std::sqrt(1 + x * x + y * y);  // n = (-y, -x, 1) / w
    worst = std::max({worst, std::fabs(vn[i][0] + y / w), std::fabs(vn[i][1] + x / w),
                      std::fabs(vn[i][2] - 1 / w)});
  }
  EXPECT_LT(worst, 1e-14);
  for (const auto& t : f) {  // triangle normal agrees with the vertex normals
    const auto& a = v[t[0] - 1];
    const auto& b = v[t[1] - 1];
    const auto& c = v[t[2] - 1];
    const double e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const double e2[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                         e1[0] * e2[1] - e1[1] * e2[0]};
    const auto& m = vn[t[0] - 1];
    EXPECT_GT(n[0] * m[0] + n[1] * m[1] + n[2] * m[2], 0);
  }
}

TEST(Export, PlyCarriesCurvaturePropertiesMatchingTheClosedForm) {
  TempDir dir;
  const auto scene = dir.file("saddle.json", saddle_scene());
  const auto ply = dir / "saddle.ply";
  const CliResult r = cli({"export", scene.string(), "-o", ply.string(), "--density", "6"});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  std::istringstream in(slurp(ply));
  std::vector<std::string> props;
  std::size_t vertices = 0;
  bool ascii = false;
  for (std::string line; std::getline(in, line) && line != "end_header";) {
    std::istringstream ls(line);
    std::string a, b, c, d;
    ls >> a >> b >> c >> d;
    if (a == "format") ascii = b == "ascii";
    if (a == "element" && b == "vertex") vertices = std::stoul(c);
    if (a == "property" && b != "list") props.push_back(c);
  }
  ASSERT_TRUE(ascii);
  ASSERT_EQ(vertices, 49u);
  const auto col = [&](const std::string& name) {
    return std::find(props.begin(), props.end(), name) - props.begin();
  };
  const auto cx = col("x"), cy = col("y"), cmean = col("mean_curvature"),
             cgauss = col("gaussian_curvature"), cnz = col("nz");
  ASSERT_LT(static_cast<std::size_t>(cmean), props.size()) << "no mean_curvature property";
  ASSERT_LT(static_cast<std::size_t>(cgauss), props.size()) << "no gaussian_curvature property";
  ASSERT_LT(static_cast<std::size_t>(cnz), props.size()) << "no normals";
  double worst = 0;
  for (std::size_t i = 0; i < vertices; ++i) {
    std::vector<double> row(props.size());
    for (double& x : row) in >> x;
    const double x = row[cx], y = row[cy], W2 = 1 + x * x + y * y;
    worst = std::max({worst, std::fabs(row[cgauss] + 1 / (W2 * W2)),
                      std::fabs(row[cmean] + x * y / std::pow(W2, 1.5)),
                      std::fabs(row[cnz] - 1 / std::sqrt(W2))});
  }
  EXPECT_LT(worst, 1e-14);
}

TEST(Export, OffAndStlAreWrittenAndAnalyzeReportsExactCurvature) {
  TempDir dir;
  const auto scene = dir.file("saddle.json", saddle_scene());
  for (const char* ext : {".off", ".stl"}) {
    const auto out = dir / (std::string("s") + ext);
    const CliResult r = cli({"export", scene.string(), "-o", out.string(), "--density", "4"});
    ASSERT_EQ(r.code, kExitOk) << r.err;
    EXPECT_GT(std::filesystem::file_size(out), 100u);
  }
  const CliResult r = cli({"analyze", scene.string(), "--json", "--density", "8"});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  // Over [0,1]^2: K = -1/W^4 is most negative at the origin (-1) and least at (1,1) (-1/9);
  // H = -xy/W^3 ranges from -1/3^1.5 at (1,1) to 0 at the axes.
  const auto j = nlohmann::json::parse(r.out);
  const auto& p = j["patches"][0];
  EXPECT_EQ(p["type"], "bezier");
  EXPECT_EQ(p["nonfinite_samples"], 0);
  EXPECT_LT(p["max_boundary_deviation"].get<double>(), 1e-15);
  EXPECT_NEAR(p["gaussian_curvature"][0].get<double>(), -1.0, 1e-12);
  EXPECT_NEAR(p["gaussian_curvature"][1].get<double>(), -1.0 / 9, 1e-12);
  EXPECT_NEAR(p["mean_curvature"][0].get<double>(), -1 / std::pow(3.0, 1.5), 1e-12);
  EXPECT_NEAR(p["mean_curvature"][1].get<double>(), 0.0, 1e-12);
}

}  // namespace
}  // namespace pl::test
