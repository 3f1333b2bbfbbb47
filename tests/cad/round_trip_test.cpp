// Round trip: every asset scene and every GB reference model exported to STEP and to IGES, read
// back with OpenCASCADE's readers, and every face compared with the patch it stands for (the
// patch evaluated here, at the same parameters): exact faces within 1e-9 of the scene size on a
// 33 x 33 grid, fitted faces within the tolerance in position and 0.05 degrees in normal at a
// grid four times denser than the fit's samples. The largest deviations seen are printed.
#include <gtest/gtest.h>

#include <BRep_Tool.hxx>
#include <STEPControl_Reader.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <cstdio>
#include <random>

#include "app/cli/load_input.hpp"
#include "cad_test_util.hpp"
#include "core/base/parallel_for.hpp"
#include "core/cad/cad_export.hpp"
#include "core/cad/occt_io.hpp"
#include "ngon_scene.hpp"

namespace pl::test {
namespace {

class TempDir {
 public:
  TempDir() {
    std::random_device rd;
    path_ = std::filesystem::temp_directory_path() / ("patchlab-cad-" + std::to_string(rd()));
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  std::filesystem::path operator/(const std::string& n) const { return path_ / n; }

 private:
  std::filesystem::path path_;
};

struct Worst {
  double exact_rel = 0, fitted_position_over_tol = 0, fitted_normal_deg = 0;
};

// Exports `scene` (read from `source`), reads it back and checks every face; accumulates the
// worst figures.
void check_round_trip(const Scene& scene, const std::filesystem::path& source, CadFormat format,
                      Worst& worst) {
  SCOPED_TRACE(source.string());
  TempDir dir;
  const auto out = dir / (format == CadFormat::Step ? "out.step" : "out.igs");
  CadExportOptions options;
  options.source = source.string();
  const CadExportReport report = export_cad(scene, out, options);
  const std::vector<CadPiece> pieces = cad_pieces(scene, std::nullopt, source.string());
  ASSERT_EQ(pieces.size(), report.faces.size());

  const CadFile back = read_cad_file(out, format);
  ASSERT_EQ(back.faces.size(), pieces.size());
  if (format == CadFormat::Step) {
    // The plain reader sees the same faces.
    STEPControl_Reader reader;
    ASSERT_EQ(reader.ReadFile(out.c_str()), IFSelect_RetDone);
    ASSERT_GT(reader.TransferRoots(), 0);
    int faces = 0;
    for (TopExp_Explorer e(reader.OneShape(), TopAbs_FACE); e.More(); e.Next()) ++faces;
    EXPECT_EQ(faces, static_cast<int>(pieces.size()));
    const std::string name = scene.name.empty() ? source.stem().string() : scene.name;
    EXPECT_EQ(back.product, name);
  }
  // Faces are matched to pieces by where they are (at the same parameters), then their names
  // are checked: in full for STEP, the 8 characters of an IGES entity label for IGES.
  std::vector<BRepAdaptor_Surface> surfaces;
  for (const auto& nf : back.faces) surfaces.emplace_back(nf.second);
  auto at = [](const BRepAdaptor_Surface& s, double u, double v) {
    const gp_Pnt p = s.Value(u, v);
    return Vec3(p.X(), p.Y(), p.Z());
  };
  std::vector<char> used(back.faces.size(), 0);
  std::vector<std::size_t> face_of(pieces.size());
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const CadPiece& piece = pieces[i];
    SCOPED_TRACE(piece.name);
    std::size_t best = 0;
    double best_d = 1e300;
    for (std::size_t k = 0; k < surfaces.size(); ++k) {
      double d = 0;
      for (Vec2 uv : {Vec2(0.5, 0.5), Vec2(0.2, 0.7), Vec2(0.8, 0.1)})
        d += glm::length(at(surfaces[k], uv.x, uv.y) - piece_truth(piece, uv).p);
      if (d < best_d) best_d = d, best = k;
    }
    ASSERT_FALSE(used[best]) << "two pieces match one face";
    used[best] = 1;
    face_of[i] = best;
    const std::string expected = format == CadFormat::Step ? piece.name : piece.name.substr(0, 8);
    EXPECT_EQ(back.faces[best].first, expected);
    EXPECT_EQ(report.faces[i].exact, piece.exact.has_value());
    if (!piece.exact) {
      ASSERT_EQ(surfaces[best].GetType(), GeomAbs_BSplineSurface);
    }
  }
  // Every face sampled against its piece (exact ones on a 33 x 33 grid, fitted ones on the check
  // grid of the surface read back), the faces in parallel: a 32-sided cap has 1.7 million
  // check points, 6 us each (the patch's evaluate() at one point, not the fit's batches).
  std::vector<Deviation> deviation(pieces.size());
  parallel_each(pieces.size(), 1, [&](std::size_t i) {
    const BRepAdaptor_Surface& s = surfaces[face_of[i]];
    if (pieces[i].exact) {
      std::vector<double> t;
      for (int k = 0; k <= 32; ++k) t.push_back(k / 32.0);
      deviation[i] = surface_deviation(pieces[i], s, t, t);
    } else {
      const CheckGrid g = fitted_check_grid(s);
      deviation[i] = surface_deviation(pieces[i], s, g.u, g.v);
    }
  });
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    SCOPED_TRACE(pieces[i].name);
    const Deviation& d = deviation[i];
    if (pieces[i].exact) {
      EXPECT_LE(d.position, 1e-9 * report.size);
      worst.exact_rel = std::max(worst.exact_rel, d.position / report.size);
    } else {
      EXPECT_LE(d.position, report.tolerance);
      EXPECT_LE(d.normal_deg, 0.05);
      worst.fitted_position_over_tol =
          std::max(worst.fitted_position_over_tol, d.position / report.tolerance);
      worst.fitted_normal_deg = std::max(worst.fitted_normal_deg, d.normal_deg);
    }
  }
}

void round_trip_all(CadFormat format) {
  Worst worst;
  const auto scenes = asset_scenes();
  ASSERT_GE(scenes.size(), 16u);
  for (const auto& f : scenes) check_round_trip(load_scene_file(f), f, format, worst);
  const auto models = reference_models();
  ASSERT_EQ(models.size(), 8u) << "the GB reference models belong in tests/data/gb";
  for (const auto& f : models) check_round_trip(load_scene_file(f), f, format, worst);
  std::printf(
      "%s round trip: exact faces within %.3g of the size; fitted faces within %.3g of "
      "the tolerance, normals within %.4f deg\n",
      format == CadFormat::Step ? "STEP" : "IGES", worst.exact_rel, worst.fitted_position_over_tol,
      worst.fitted_normal_deg);
}

TEST(CadRoundTrip, EveryAssetSceneAndReferenceModelThroughStep) {
  round_trip_all(CadFormat::Step);
}

TEST(CadRoundTrip, EveryAssetSceneAndReferenceModelThroughIges) {
  round_trip_all(CadFormat::Iges);
}

// Faces of the sizes users reach: a regular n-gon GB cap (a ring split, a singular corner per
// side), alone or inside a ring of Gregory quads, exported to STEP and read back.
void round_trip_ngon(int n, bool ring) {
  Worst worst;
  const Scene scene = ngon_cap_scene(n, ring);
  check_round_trip(scene, scene.name + (ring ? " in a ring of quads" : ""), CadFormat::Step, worst);
  std::printf("%d-gon%s: fitted faces within %.3g of the tolerance, normals within %.4f deg\n", n,
              ring ? " in a ring of quads" : "", worst.fitted_position_over_tol,
              worst.fitted_normal_deg);
}

TEST(CadRoundTrip, SixteenSidedGBFaceInARingOfQuadsThroughStep) {
  round_trip_ngon(16, true);
}

// The largest cap cheap enough for a test (most of its time goes to the check points of its 96
// faces, each patch evaluated on its own); the 64-sided one is timed by the benchmark
// (tests/bench/cad_ngon_bench.cpp).
TEST(CadRoundTrip, ThirtyTwoSidedGBCapThroughStep) {
  round_trip_ngon(32, false);
}

}  // namespace
}  // namespace pl::test
