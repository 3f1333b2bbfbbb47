#include <charconv>
#include <cmath>

#include "app/cli/arguments.hpp"
#include "app/cli/checked_scene.hpp"
#include "app/cli/cli.hpp"
#include "app/cli/commands.hpp"
#include "app/cli/load_input.hpp"
#include "app/cli/progress_line.hpp"
#include "app/cli/scene_outputs.hpp"
#include "app/cli/work_limits.hpp"
#include "core/base/parallel_for.hpp"
#include "core/cad/cad_export.hpp"
#include "core/io/input_limits.hpp"
#include "core/io/json_node.hpp"
#include "core/mesh/mesh_export.hpp"
#include "core/mesh/polyline.hpp"

namespace pl {

namespace {

double tolerance_option(const std::string& v) {
  double t = 0;
  const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), t);
  if (ec != std::errc() || end != v.data() + v.size() || !(t > 0) || !std::isfinite(t))
    throw UsageError("--tolerance takes a positive number, got \"" + v + "\"");
  return t;
}

// STEP / IGES: B-spline faces through OpenCASCADE (core/cad/cad_export.hpp), after the checks
// every command runs (at the default density: what `analyze FILE` refuses is refused here with
// the same message); the CAD writers check their own size range and work bounds.
int export_cad_file(const Arguments& a, const std::string& target, std::ostream& out) {
  if (a.value("--density")) throw UsageError("--density applies to mesh output only");
  CadExportOptions options;
  if (const auto t = a.value("--tolerance")) options.tolerance = tolerance_option(*t);
  options.scheme = parse_scheme_option(a.value("--scheme"));
  options.source = a.positional()[0];
  ProgressLine::set_stage("reading " + printable(options.source));
  const Scene scene = load_scene_file(options.source);
  // A scene too big for the work bound at the default density is checked at the largest density
  // within it (the CAD writers sample nothing at a density).
  const int density = std::max(1, largest_density_within(scene, kDefaultDensity));
  TessellationCache cache;
  evaluate_checked(scene, density, options.scheme, cache, options.source);
  ProgressLine::set_stage("fitting and writing " + printable(target));
  out << cad_report_text(export_cad(scene, target, options));
  return kExitOk;
}

}  // namespace

MeshExportCount export_mesh_file(const Scene& scene, const std::filesystem::path& target,
                                 int density, std::optional<FaceScheme> scheme,
                                 const std::string& source) {
  const MeshFormat format = mesh_format_for(target);  // an unknown format before any work
  TessellationCache cache;
  const SceneSurfaces surfaces = evaluate_checked(scene, density, scheme, cache, source);
  std::vector<SurfaceMesh> meshes(surfaces.surfaces.size());
  parallel_each(meshes.size(), 4, [&](std::size_t i) {
    meshes[i] = make_surface_mesh(*surfaces.surfaces[i].evaluator, surfaces.surfaces[i].name);
  });
  std::vector<CurvePolyline> polylines;
  if (format == MeshFormat::Obj)
    for (std::size_t i = 0; i < scene.curves.size(); ++i)
      polylines.push_back(curve_polyline(scene.curves[i], curve_name(scene.curves[i], i), density));
  ProgressLine::set_stage("writing " + printable(target.string()));
  export_meshes(meshes, target, source, polylines);
  return {meshes.size(), polylines.size()};
}

std::string mesh_export_summary(const MeshExportCount& n, const std::string& target) {
  std::string s = "wrote " + std::to_string(n.patches) + " patch(es)";
  if (n.curves > 0) s += " and " + std::to_string(n.curves) + " curve(s)";
  return s + " to " + printable(target) + "\n";
}

int run_export(std::span<const std::string> args, std::ostream& out, std::ostream&) {
  const Arguments a(args, {"-o", "--density", "--scheme", "--tolerance"}, {});
  if (a.positional().size() != 1) throw UsageError("export takes exactly one input FILE");
  const auto target = a.value("-o");
  if (!target) throw UsageError("export needs -o OUT.{obj,ply,off,stl,step,stp,igs,iges}");
  const std::string file = a.positional()[0];
  check_input_name(file);
  // The output's extension is part of the command line: an unknown one is wrong usage, as for
  // `render` and `convert`.
  const auto mesh_format = find_mesh_format(*target);
  if (!mesh_format && !cad_format_for(*target))
    throw UsageError("export writes .obj, .ply, .off, .stl, .step, .stp, .igs or .iges, not \"" +
                     std::filesystem::path(*target).extension().string() + "\"");
  if (!mesh_format) return export_cad_file(a, *target, out);
  if (a.value("--tolerance")) throw UsageError("--tolerance applies to STEP and IGES output only");
  const int density = a.integer("--density", kDefaultDensity, 1, kMaxDensity);
  const auto scheme = parse_scheme_option(a.value("--scheme"));
  ProgressLine::set_stage("reading " + printable(file));
  const Scene scene = load_scene_file(file);
  out << mesh_export_summary(export_mesh_file(scene, *target, density, scheme, file), *target);
  return kExitOk;
}

}  // namespace pl
