// The curves of STEP and IGES files as free curves: curves exported by PatchLab come back as
// the same curves (evaluated at their own parameters; STEP keeps them whole,
// IGES splits them at their C0 knots), the edges of a surface model come back once each, and
// files that are not CAD are refused by name.
#include "core/cad/cad_curves.hpp"

#include <gtest/gtest.h>

#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <filesystem>
#include <fstream>
#include <random>
#include <set>

#include "core/base/data_error.hpp"
#include "core/cad/occt_io.hpp"
#include "core/io/scene_io.hpp"

namespace pl {
namespace {

struct Dir {
  Dir() {
    std::random_device rd;
    path = std::filesystem::temp_directory_path() / ("patchlab-cadcurves-" + std::to_string(rd()));
    std::filesystem::create_directories(path);
  }
  ~Dir() {
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
  }
  std::filesystem::path path;
};

Scene curves_scene() {
  Scene s;
  s.name = "curves";
  for (const char* name : {"nurbs-circle-and-conics.json", "interpolating-hermite-bezier.json"}) {
    const Scene f =
        read_scene(std::filesystem::path(PATCHLAB_SOURCE_DIR) / "assets" / "curves" / name);
    s.curves.insert(s.curves.end(), f.curves.begin(), f.curves.end());
  }
  return s;
}

// Largest distance between `back` and `original` at 200 parameters of back's range, relative
// to original's size (both evaluated at the same parameter).
double difference(const SceneCurve& back, const SceneCurve& original) {
  const auto pts = spline_form(original).points;
  Vec3 lo = pts[0], hi = pts[0];
  for (const Vec3& q : pts) lo = glm::min(lo, q), hi = glm::max(hi, q);
  double worst = 0;
  for (int i = 0; i <= 200; ++i) {
    const double t = back.t_min() + (back.t_max() - back.t_min()) * i / 200.0;
    worst = std::max(worst, glm::length(evaluate(back, t).p - evaluate(original, t).p));
  }
  return worst / glm::length(hi - lo);
}

TEST(CadCurves, ExportedCurvesComeBack) {
  Dir dir;
  const Scene scene = curves_scene();
  ASSERT_GE(scene.curves.size(), 4u);
  CadExportOptions o;
  o.source = "test";
  const auto step = dir.path / "c.step";
  export_cad(scene, step, o);
  const CadCurves back = read_cad_curves(step);
  ASSERT_EQ(back.curves.size(), scene.curves.size());
  std::set<std::string> names;
  for (std::size_t i = 0; i < back.curves.size(); ++i) {
    EXPECT_LE(difference(back.curves[i], scene.curves[i]), 1e-9) << scene.curves[i].name;
    names.insert(back.curves[i].name);
  }
  EXPECT_EQ(names.size(), back.curves.size()) << "every curve named, each differently";
  const auto iges = dir.path / "c.igs";
  export_cad(scene, iges, o);
  const CadCurves pieces = read_cad_curves(iges);
  // In order, the pieces cover each curve's range.
  std::size_t k = 0;
  for (const SceneCurve& c : scene.curves) {
    double covered = c.t_min();
    while (covered < c.t_max() - 1e-12) {
      ASSERT_LT(k, pieces.curves.size()) << c.name;
      const SceneCurve& p = pieces.curves[k++];
      EXPECT_NEAR(p.t_min(), covered, 1e-12) << c.name;
      EXPECT_LE(difference(p, c), 1e-9) << c.name;
      covered = p.t_max();
    }
  }
  EXPECT_EQ(k, pieces.curves.size());
}

TEST(CadCurves, TheEdgesOfASurfaceModelComeOnceEach) {
  Dir dir;
  const Scene scene =
      read_scene(std::filesystem::path(PATCHLAB_SOURCE_DIR) / "assets" / "default.json");
  CadExportOptions o;
  o.source = "test";
  const auto step = dir.path / "model.step";
  export_cad(scene, step, o);
  const CadFile file = read_cad_file(step, CadFormat::Step);
  TopTools_IndexedMapOfShape edges;
  TopExp::MapShapes(file.shape, TopAbs_EDGE, edges);
  const CadCurves back = read_cad_curves(step);
  EXPECT_EQ(back.curves.size() + back.passed_over, std::size_t(edges.Extent()));
  EXPECT_GE(back.curves.size(), 7u);  // the default scene's two faces have 7 sides
  for (const SceneCurve& c : back.curves) EXPECT_NO_THROW(validate_curve(c)) << c.name;
}

TEST(CadCurves, WhatIsNotCadIsRefusedByName) {
  Dir dir;
  const auto text = dir.path / "notes.step";
  std::ofstream(text) << "this is not STEP\n";
  try {
    read_cad_curves(text);
    ADD_FAILURE();
  } catch (const DataError& e) {
    EXPECT_NE(std::string(e.what()).find("notes.step"), std::string::npos) << e.what();
  }
  EXPECT_THROW(read_cad_curves(dir.path / "a.json"), DataError);
  EXPECT_THROW(read_cad_curves(dir.path / "missing.igs"), DataError);
}

}  // namespace
}  // namespace pl
