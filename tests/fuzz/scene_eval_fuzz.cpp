// libFuzzer target: what the readers accept, evaluated as `patchlab analyze` and `export` do:
// work limits, evaluation at a small density (the first byte picks 1..8), the finiteness check
// every writer runs, the analysis, and the mesh arrays. Input starting with a digit is a .gbp
// file, anything else a scene.
#include <cctype>
#include <cmath>

#include "app/cli/work_limits.hpp"
#include "core/analysis/scene_analysis.hpp"
#include "core/base/data_error.hpp"
#include "core/domain/tessellation_cache.hpp"
#include "core/eval/scene_surfaces.hpp"
#include "core/io/gbp_io.hpp"
#include "core/io/scene_io.hpp"
#include "core/mesh/finite_check.hpp"
#include "core/mesh/surface_mesh.hpp"
#include "fuzz_common.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const int density = 1 + data[0] % 8;
  const std::string text = pl::fuzz::text(data + 1, size - 1);
  try {
    pl::Scene scene;
    if (!text.empty() && std::isdigit(static_cast<unsigned char>(text[0])))
      scene.patches.push_back({"", std::make_shared<pl::GBPatch>(pl::parse_gbp(text, "fuzz.gbp"))});
    else
      scene = pl::parse_scene(text, "fuzz.json");
    pl::check_work_limits(scene, density, "fuzz");
    pl::TessellationCache cache;
    const pl::SceneSurfaces surfaces =
        pl::evaluate_scene(scene, density, std::nullopt, cache, "fuzz");
    std::vector<pl::SurfaceMesh> meshes;
    for (const pl::SceneSurface& s : surfaces.surfaces) {
      pl::check_finite(*s.evaluator, s.name, "fuzz");
      meshes.push_back(pl::make_surface_mesh(*s.evaluator, s.name));
    }
    pl::check_finite(meshes, "fuzz");
    // Finite by construction: the report of finite samples holds finite numbers.
    const pl::SceneReport r = pl::analyze_scene(scene, surfaces);
    for (const pl::PatchReport& p : r.patches)
      for (double x :
           {p.max_boundary_deviation, p.gaussian[0], p.gaussian[1], p.mean[0], p.mean[1]})
        if (!std::isfinite(x)) __builtin_trap();
    for (const pl::EdgeReport& e : r.edges)
      for (double x : {e.max_gap, e.max_normal_angle_deg, e.max_mean_curvature_jump})
        if (!std::isfinite(x)) __builtin_trap();
    pl::report_to_json(r);
  } catch (const pl::DataError&) {
  }
  return 0;
}
