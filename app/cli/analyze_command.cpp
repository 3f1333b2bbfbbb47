#include "app/cli/arguments.hpp"
#include "app/cli/checked_scene.hpp"
#include "app/cli/cli.hpp"
#include "app/cli/commands.hpp"
#include "app/cli/load_input.hpp"
#include "app/cli/progress_line.hpp"
#include "app/cli/scene_outputs.hpp"
#include "core/analysis/scene_analysis.hpp"
#include "core/io/input_limits.hpp"
#include "core/io/json_node.hpp"

namespace pl {

SceneReport analyze_input(const Scene& scene, int density, std::optional<FaceScheme> scheme,
                          const std::string& source) {
  TessellationCache cache;
  // The report's figures are finite only if every sample is.
  std::vector<CurveReport> curves;
  const SceneSurfaces surfaces = evaluate_checked(scene, density, scheme, cache, source, &curves);
  ProgressLine::set_stage("analysing");
  return analyze_scene(scene, surfaces, std::move(curves));
}

int run_analyze(std::span<const std::string> args, std::ostream& out, std::ostream&) {
  const Arguments a(args, {"--density", "--scheme"}, {"--json"});
  if (a.positional().size() != 1) throw UsageError("analyze takes exactly one input FILE");
  const int density = a.integer("--density", kDefaultDensity, 1, kMaxDensity);
  const auto scheme = parse_scheme_option(a.value("--scheme"));
  const std::string file = a.positional()[0];
  check_input_name(file);
  ProgressLine::set_stage("reading " + printable(file));
  const SceneReport report = analyze_input(load_scene_file(file), density, scheme, file);
  out << (a.flag("--json") ? report_to_json(report) : report_to_text(report));
  return kExitOk;
}

}  // namespace pl
