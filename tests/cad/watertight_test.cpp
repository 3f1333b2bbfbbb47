// Closed networks export as one closed shell: the blob (Gregory triangles and quads, valence 3,
// 4 and 5) and the 96-face cube-sphere, with either filling scheme, through STEP and IGES. The
// files are read back with STEPControl_Reader / IGESControl_Reader and measured there: no free
// edge, every sewn edge's gap within 1e-9 of the scene size (pinned boundaries meet exactly),
// normals across sewn edges within 0.1 degrees (each side within 0.05 of the G1 filling).
#include <gtest/gtest.h>

#include <IGESControl_Reader.hxx>
#include <STEPControl_Reader.hxx>
#include <cstdio>
#include <random>

#include "app/cli/load_input.hpp"
#include "cad_test_util.hpp"
#include "core/cad/cad_export.hpp"
#include "core/cad/occt_shape.hpp"
#include "core/network/sample_networks.hpp"

namespace pl::test {
namespace {

TopoDS_Shape read_back(const std::filesystem::path& file, CadFormat format) {
  if (format == CadFormat::Step) {
    STEPControl_Reader r;
    EXPECT_EQ(r.ReadFile(file.c_str()), IFSelect_RetDone);
    r.TransferRoots();
    return r.OneShape();
  }
  IGESControl_Reader r;
  EXPECT_EQ(r.ReadFile(file.c_str()), IFSelect_RetDone);
  r.TransferRoots();
  return r.OneShape();
}

void check_closed(const Scene& scene, const std::string& what, std::optional<FaceScheme> scheme,
                  CadFormat format) {
  SCOPED_TRACE(what);
  const auto out = std::filesystem::temp_directory_path() /
                   ("patchlab-watertight-" + std::to_string(std::random_device()()) +
                    (format == CadFormat::Step ? ".step" : ".igs"));
  CadExportOptions options;
  options.scheme = scheme;
  options.source = what;
  const CadExportReport report = export_cad(scene, out, options);
  // As the export measured it before writing...
  EXPECT_EQ(report.free_edges, 0);
  EXPECT_EQ(report.closed_shells, 1);
  EXPECT_EQ(report.solids, 1);
  // ...and on the file as read back.
  const TopoDS_Shape shape = read_back(out, format);
  std::filesystem::remove(out);
  ASSERT_FALSE(shape.IsNull());
  const ShellReport r = analyze_shell(shape);
  EXPECT_EQ(r.faces, static_cast<int>(report.faces.size()));
  EXPECT_EQ(r.shells, 1);
  EXPECT_EQ(r.closed_shells, 1);
  EXPECT_EQ(r.free_edges, 0);
  EXPECT_EQ(r.multiple_edges, 0);
  EXPECT_GT(r.sewn_edges, 0);
  EXPECT_LE(r.max_gap, 1e-9 * report.size);
  EXPECT_LE(r.max_normal_angle_deg, 0.1);
  std::printf(
      "%s %s (%s): %d faces, %d sewn edges, 0 free: largest gap %.3g of the size, "
      "largest normal angle %.4f deg\n",
      format == CadFormat::Step ? "STEP" : "IGES", what.c_str(),
      scheme == FaceScheme::GB ? "gb" : "default", r.faces, r.sewn_edges, r.max_gap / report.size,
      r.max_normal_angle_deg);
}

Scene blob() {
  return load_scene_file(source_dir() / "assets/gregory-blob-closed.json");
}

Scene cube_sphere() {
  Scene s;
  s.name = "cube sphere 4x4";
  s.network = cube_sphere_network(4);
  return s;
}

TEST(CadWatertight, BlobIsOneClosedShell) {
  for (CadFormat f : {CadFormat::Step, CadFormat::Iges}) {
    check_closed(blob(), "blob", std::nullopt, f);
    check_closed(blob(), "blob", FaceScheme::GB, f);
  }
}

TEST(CadWatertight, CubeSphere96IsOneClosedShell) {
  for (CadFormat f : {CadFormat::Step, CadFormat::Iges})
    check_closed(cube_sphere(), "cube-sphere 96", std::nullopt, f);
  check_closed(cube_sphere(), "cube-sphere 96", FaceScheme::GB, CadFormat::Step);
}

}  // namespace
}  // namespace pl::test
