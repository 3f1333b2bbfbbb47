#include "app/cli/arguments.hpp"
#include "app/cli/cli.hpp"
#include "app/cli/commands.hpp"
#include "app/cli/load_input.hpp"
#include "app/cli/progress_line.hpp"
#include "app/cli/scene_outputs.hpp"
#include "app/cli/work_limits.hpp"
#include "core/analysis/scene_analysis.hpp"
#include "core/io/input_limits.hpp"
#include "core/mesh/finite_check.hpp"

namespace pl {

SceneSurfaces evaluate_checked(const Scene& scene, int density, std::optional<FaceScheme> scheme,
                               TessellationCache& cache, const std::string& source) {
  check_work_limits(scene, density, source);
  ProgressLine::set_stage("evaluating the surfaces");
  SceneSurfaces surfaces = evaluate_scene(scene, density, scheme, cache, source);
  // Every figure made from them is finite only if every sample is.
  for (const SceneSurface& s : surfaces.surfaces) check_finite(*s.evaluator, s.name, source);
  for (std::size_t i = 0; i < scene.curves.size(); ++i)
    check_curve_finite(scene.curves[i], i, density, source);
  return surfaces;
}

SceneReport analyze_input(const Scene& scene, int density, std::optional<FaceScheme> scheme,
                          const std::string& source) {
  TessellationCache cache;
  const SceneSurfaces surfaces = evaluate_checked(scene, density, scheme, cache, source);
  return analyze_scene(scene, surfaces, density);
}

int run_analyze(std::span<const std::string> args, std::ostream& out, std::ostream&) {
  const Arguments a(args, {"--density", "--scheme"}, {"--json"});
  if (a.positional().size() != 1) throw UsageError("analyze takes exactly one input FILE");
  const int density = a.integer("--density", 32, 1, kMaxDensity);
  const auto scheme = parse_scheme_option(a.value("--scheme"));
  const std::string file = a.positional()[0];
  const SceneReport report = analyze_input(load_input(file), density, scheme, file);
  out << (a.flag("--json") ? report_to_json(report) : report_to_text(report));
  return kExitOk;
}

}  // namespace pl
