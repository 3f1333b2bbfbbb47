#include "app/cli/arguments.hpp"
#include "app/cli/cli.hpp"
#include "app/cli/commands.hpp"
#include "app/cli/load_input.hpp"
#include "app/cli/work_limits.hpp"
#include "core/analysis/scene_analysis.hpp"
#include "core/io/input_limits.hpp"
#include "core/mesh/finite_check.hpp"

namespace pl {

int run_analyze(std::span<const std::string> args, std::ostream& out, std::ostream&) {
  const Arguments a(args, {"--density", "--scheme"}, {"--json"});
  if (a.positional().size() != 1) throw UsageError("analyze takes exactly one input FILE");
  const int density = a.integer("--density", 32, 1, kMaxDensity);
  const auto scheme = parse_scheme_option(a.value("--scheme"));
  const std::string file = a.positional()[0];
  const Scene scene = load_input(file);
  check_work_limits(scene, density, file);
  TessellationCache cache;
  const SceneSurfaces surfaces = evaluate_scene(scene, density, scheme, cache, file);
  // The report's figures are finite only if every sample is.
  for (const SceneSurface& s : surfaces.surfaces) check_finite(*s.evaluator, s.name, file);
  for (std::size_t i = 0; i < scene.curves.size(); ++i)
    check_curve_finite(scene.curves[i], i, density, file);
  const SceneReport report = analyze_scene(scene, surfaces, density);
  out << (a.flag("--json") ? report_to_json(report) : report_to_text(report));
  return kExitOk;
}

}  // namespace pl
