// Free curves in STEP and IGES: OpenCASCADE's own Geom_BSplineCurve evaluates the exported
// curve to the scene curve's points (1,000 samples, 1e-13 of the size), and the files read back
// hold one edge per curve on the same curve (to the precision the file's numbers keep).
#include <gtest/gtest.h>

#include <BRep_Tool.hxx>
#include <Geom_Curve.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <filesystem>
#include <random>

#include "core/cad/cad_export.hpp"
#include "core/cad/curve_edges.hpp"
#include "core/cad/occt_io.hpp"
#include "core/io/scene_io.hpp"

namespace pl {
namespace {

std::vector<SceneCurve> test_curves() {
  std::vector<SceneCurve> all;
  for (const char* name : {"nurbs-circle-and-conics.json", "bspline-knot-multiplicity.json",
                           "interpolating-hermite-bezier.json", "joints-g0-g1-g2.json"}) {
    const Scene s =
        read_scene(std::filesystem::path(PATCHLAB_SOURCE_DIR) / "assets" / "curves" / name);
    all.insert(all.end(), s.curves.begin(), s.curves.end());
  }
  // An unclamped rational cubic with a double knot.
  SceneCurve c;
  c.type = CurveType::Nurbs;
  c.name = "unclamped";
  c.degree = 3;
  c.knots = {-0.5, -0.2, 0, 0.1, 0.3, 0.3, 0.7, 0.9, 1.2, 1.4, 1.5};
  c.points = {{0, 0, 0}, {1, 2, 0.5}, {2, -1, 0}, {3, 1, 1}, {4, 0, -1}, {5, 2, 0}, {6, 1, 0.5}};
  c.weights = {1, 0.5, 2, 1.5, 0.7, 1, 3};
  validate_curve(c);
  all.push_back(c);
  return all;
}

double size_of(const SceneCurve& c) {
  const auto pts = spline_form(c).points;
  Vec3 lo = pts[0], hi = pts[0];
  for (const Vec3& q : pts) lo = glm::min(lo, q), hi = glm::max(hi, q);
  return glm::length(hi - lo);
}

double worst_difference(const SceneCurve& c, const Handle(Geom_Curve) & g, double a, double b) {
  double worst = 0;
  for (int i = 0; i < 1000; ++i) {
    const double t = a + (b - a) * i / 999.0;
    const gp_Pnt q = g->Value(t);
    worst = std::max(worst, glm::length(Vec3(q.X(), q.Y(), q.Z()) - evaluate(c, t).p));
  }
  return worst / size_of(c);
}

TEST(CurveExport, OcctCurveIsTheSceneCurve) {
  for (const SceneCurve& c : test_curves()) {
    const Handle(Geom_BSplineCurve) g = occt_curve(c);
    EXPECT_EQ(g->Degree(), curve_degree(c)) << c.name;
    // OCCT calls a curve with equal weights (the parabola arc) polynomial.
    bool rational = false;
    for (double w : c.weights) rational = rational || w != c.weights.front();
    EXPECT_EQ(g->IsRational(), rational) << c.name;
    EXPECT_DOUBLE_EQ(g->FirstParameter(), c.t_min());
    EXPECT_DOUBLE_EQ(g->LastParameter(), c.t_max());
    EXPECT_LE(worst_difference(c, g, c.t_min(), c.t_max()), 1e-13) << c.name;
  }
}

TEST(CurveExport, FilesReadBackHoldEveryCurve) {
  std::random_device rd;
  const auto dir =
      std::filesystem::temp_directory_path() / ("patchlab-curves-" + std::to_string(rd()));
  std::filesystem::create_directories(dir);
  Scene scene;
  scene.name = "curves";
  scene.curves = test_curves();
  for (const auto& [ext, format] :
       {std::pair{".step", CadFormat::Step}, std::pair{".igs", CadFormat::Iges}}) {
    const auto file = dir / (std::string("c") + ext);
    CadExportOptions o;
    o.source = "test";
    const CadExportReport r = export_cad(scene, file, o);
    EXPECT_EQ(r.curves, int(scene.curves.size()));
    const CadFile back = read_cad_file(file, format);
    std::vector<TopoDS_Edge> edges;
    for (TopExp_Explorer e(back.shape, TopAbs_EDGE); e.More(); e.Next())
      edges.push_back(TopoDS::Edge(e.Current()));
    // OCCT's IGES reader splits a curve at its C0 knots (the circle's quarters): the edges, in
    // order, cover each curve's range.
    std::size_t e = 0;
    for (const SceneCurve& c : scene.curves) {
      double covered = c.t_min();
      while (covered < c.t_max()) {
        ASSERT_LT(e, edges.size()) << ext << " " << c.name;
        double a = 0, b = 0;
        const Handle(Geom_Curve) g = BRep_Tool::Curve(edges[e++], a, b);
        ASSERT_FALSE(g.IsNull()) << ext << " " << c.name;
        EXPECT_NEAR(a, covered, 1e-12) << ext << " " << c.name;
        EXPECT_LE(worst_difference(c, g, a, b), 1e-9) << ext << " " << c.name;
        EXPECT_GT(b, a) << ext << " " << c.name;
        covered = b;
      }
      EXPECT_NEAR(covered, c.t_max(), 1e-12) << ext << " " << c.name;
    }
    EXPECT_EQ(e, edges.size()) << ext;
    if (format == CadFormat::Step) {
      EXPECT_EQ(edges.size(), scene.curves.size());
    }
  }
  std::error_code ec;
  std::filesystem::remove_all(dir, ec);
}

}  // namespace
}  // namespace pl
