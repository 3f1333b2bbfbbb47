#include "app/cli/checked_scene.hpp"

#include "app/cli/progress_line.hpp"
#include "app/cli/work_limits.hpp"
#include "core/analysis/curve_analysis.hpp"
#include "core/mesh/finite_check.hpp"

namespace pl {

SceneSurfaces evaluate_checked(const Scene& scene, int density, std::optional<FaceScheme> scheme,
                               TessellationCache& cache, const std::string& file,
                               std::vector<CurveReport>* curve_reports,
                               const std::shared_ptr<SampleBufferPool>& pool) {
  check_work_limits(scene, density, file);
  ProgressLine::set_stage("evaluating the surfaces");
  SceneSurfaces surfaces = evaluate_scene(scene, density, scheme, cache, file, pool);
  for (const SceneSurface& s : surfaces.surfaces) check_finite(*s.evaluator, s.name, file);
  ProgressLine::set_stage("evaluating the curves");
  for (std::size_t i = 0; i < scene.curves.size(); ++i) {
    if (curve_reports)
      curve_reports->push_back(checked_curve_report(scene.curves[i], i, density, file));
    else
      check_curve_finite(scene.curves[i], i, density, file);
  }
  return surfaces;
}

}  // namespace pl
