// `patchlab compare`: the quality figures of several face schemes over the same network faces
// (core/analysis/scheme_comparison.hpp), as a table or as JSON (docs/cli.md).
#include "app/cli/arguments.hpp"
#include "app/cli/cli.hpp"
#include "app/cli/commands.hpp"
#include "app/cli/load_input.hpp"
#include "app/cli/progress_line.hpp"
#include "app/cli/work_limits.hpp"
#include "core/analysis/compared_schemes.hpp"
#include "core/analysis/scheme_comparison.hpp"
#include "core/base/data_error.hpp"
#include "core/io/input_limits.hpp"

namespace pl {

namespace {

// A face by name or by index.
int face_option(const Network& net, const std::string& item, const std::string& file) {
  for (std::size_t f = 0; f < net.faces.size(); ++f)
    if (net.faces[f].name == item) return int(f);
  if (!item.empty() && item.find_first_not_of("0123456789") == std::string::npos &&
      item.size() < 10) {
    const int f = std::stoi(item);
    if (f < int(net.faces.size())) return f;
  }
  throw DataError(file, "network.faces",
                  "--faces: no face named or numbered \"" + item + "\" (the network has " +
                      std::to_string(net.faces.size()) + " faces)");
}

}  // namespace

int run_compare(std::span<const std::string> args, std::ostream& out, std::ostream&) {
  const Arguments a(args, {"--schemes", "--base", "--faces", "--density"}, {"--json"});
  if (a.positional().size() != 1) throw UsageError("compare takes exactly one input FILE");
  const int density = a.integer("--density", 32, 1, kMaxDensity);
  ComparisonOptions options;
  options.density = density;
  if (const auto list = a.value("--schemes"))
    options.schemes = parse_scheme_list(*list, "--schemes");
  if (const auto base = a.value("--base")) options.base = parse_comparable_scheme(*base, "--base");
  const std::string file = a.positional()[0];
  const Scene scene = load_scene_file(file);
  if (!scene.network || scene.network->faces.empty())
    throw DataError(file, "network", "the scene has no network faces to compare");
  if (const auto list = a.value("--faces"))
    for (const std::string& item : split_list(*list, "--faces"))
      options.faces.push_back(face_option(*scene.network, item, file));
  check_work_limits(scene, density, file);
  ProgressLine::set_stage("filling and measuring the faces");
  const SchemeComparison c = compare_schemes(scene, options, file);
  out << (a.flag("--json") ? comparison_to_json(c) : comparison_to_text(c));
  return kExitOk;
}

}  // namespace pl
