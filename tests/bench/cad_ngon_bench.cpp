// Figures of the STEP export of many-sided GB faces: one n-sided network GB face (a regular n-gon
// cap of the unit sphere, tests/cad/ngon_scene.hpp) for n = 8, 16, 32, 64, and the 16-sided cap
// in a ring of 16 Gregory quads (a network whose n-gon shares every edge), each measured in the
// same run as its baseline, the 4-sided cap (in its ring of 4 quads). Printed: the whole export
// (fits, sewing, STEP written) in ms, its ratio to the 4-sided one, the faces written (a face of
// n >= 13 sides is 3n pieces), the control points per face, the time per face over the
// 4-sided one's (it grows with n: every sample blends all n ribbons, and each ring piece grades
// its knots towards a singular corner of the patch and across its sharp rim), and the largest
// deviation of a fitted face (position over the tolerance, normal in degrees).
// The 64-sided cap exports in about 9 s on 2 cores (16 s of CPU time), within the bound
// docs/limits.md states for it.
#include <algorithm>
#include <filesystem>
#include <random>

#include "bench_common.hpp"
#include "core/cad/cad_export.hpp"
#include "tests/cad/ngon_scene.hpp"

namespace pl::bench {

void bench_cad_ngon(const Options& o) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("patchlab-bench-cad-ngon-" + std::to_string(std::random_device()()));
  std::filesystem::create_directories(dir);
  const auto run = [&](bool ring, const std::vector<int>& sides) {
    const std::string what = ring ? "gb_ring_" : "gb_";
    double base_ms = 0, base_per_face = 0;
    for (int n : sides) {
      const Scene scene = test::ngon_cap_scene(n, ring);
      CadExportReport report;
      const double ms = median_ms(o.quick || n >= 16 ? 1 : 3, [&] {
        report = export_cad(scene, dir / "ngon.step", {std::nullopt, std::nullopt, "bench"});
      });
      const double faces = double(report.faces.size());
      std::size_t points = 0;
      double position = 0, normal = 0;
      for (const CadFaceReport& f : report.faces) {
        points += f.control_points;
        if (f.exact) continue;
        position = std::max(position, f.position_deviation);
        normal = std::max(normal, f.normal_deviation_deg);
      }
      if (n == sides.front()) base_ms = ms, base_per_face = ms / faces;
      const std::string tag = "cad_step_export_" + what + std::to_string(n) + "_sides";
      figure((tag + "_ms").c_str(), ms, "ms");
      figure((tag + "_vs_4").c_str(), ms / base_ms, "x");
      figure((tag + "_faces").c_str(), faces, "faces");
      figure((tag + "_points_per_face").c_str(), double(points) / faces, "points");
      figure((tag + "_ms_per_face_vs_4").c_str(), ms / faces / base_per_face, "x");
      figure((tag + "_deviation_vs_tolerance").c_str(), position / report.tolerance, "x");
      figure((tag + "_normal_deviation").c_str(), normal, "deg");
    }
  };
  run(false, o.quick ? std::vector<int>{4, 8} : std::vector<int>{4, 8, 16, 32, 64});
  if (!o.quick) run(true, {4, 16});
  std::error_code ec;
  std::filesystem::remove_all(dir, ec);
}

}  // namespace pl::bench
