// Figures of the STEP/IGES export: the whole export (exact or fitted faces, sewing, STEP
// written to a temporary file) of the 96- and 1,536-face cube-spheres at the default tolerance,
// the control points written per face, and as the baseline measured in the same run the OBJ
// export of the same scene at the default density (32).
#include <filesystem>
#include <random>

#include "bench_common.hpp"
#include "core/cad/cad_export.hpp"
#include "core/eval/scene_surfaces.hpp"
#include "core/mesh/mesh_export.hpp"
#include "core/network/sample_networks.hpp"

namespace pl::bench {

void bench_cad(const Options& o) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("patchlab-bench-cad-" + std::to_string(std::random_device()()));
  std::filesystem::create_directories(dir);
  for (int k : o.quick ? std::vector<int>{2} : std::vector<int>{4, 16}) {
    Scene scene;
    scene.name = "cube sphere";
    scene.network = cube_sphere_network(k);
    const int faces = 6 * k * k;
    const std::string tag = std::to_string(faces);
    CadExportReport report;
    const double cad_ms = median_ms(o.quick ? 1 : 3, [&] {
      report = export_cad(scene, dir / "cs.step", {std::nullopt, std::nullopt, "bench"});
    });
    const double obj_ms = median_ms(o.quick ? 1 : 3, [&] {
      TessellationCache cache;
      const SceneSurfaces s = evaluate_scene(scene, 32, std::nullopt, cache, "bench");
      std::vector<SurfaceMesh> meshes;
      for (const SceneSurface& f : s.surfaces)
        meshes.push_back(make_surface_mesh(*f.evaluator, f.name));
      export_meshes(meshes, dir / "cs.obj");
    });
    std::size_t points = 0, most = 0;
    for (const CadFaceReport& f : report.faces) {
      points += f.control_points;
      most = std::max(most, f.control_points);
    }
    figure(("cad_step_export_cube_sphere_" + tag + "_ms").c_str(), cad_ms, "ms");
    figure(("cad_obj_export_cube_sphere_" + tag + "_ms").c_str(), obj_ms, "ms");
    figure(("cad_step_vs_obj_cube_sphere_" + tag).c_str(), cad_ms / obj_ms, "x");
    figure(("cad_control_points_per_face_cube_sphere_" + tag).c_str(),
           double(points) / report.faces.size(), "points");
    figure(("cad_control_points_max_face_cube_sphere_" + tag).c_str(), double(most), "points");
    figure(("cad_step_bytes_cube_sphere_" + tag).c_str(),
           double(std::filesystem::file_size(dir / "cs.step")), "bytes");
  }
  std::error_code ec;
  std::filesystem::remove_all(dir, ec);
}

}  // namespace pl::bench
