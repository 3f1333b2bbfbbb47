#include <charconv>
#include <cmath>

#include "app/cli/arguments.hpp"
#include "app/cli/cli.hpp"
#include "app/cli/commands.hpp"
#include "app/cli/load_input.hpp"
#include "app/cli/work_limits.hpp"
#include "core/analysis/curve_analysis.hpp"
#include "core/cad/cad_export.hpp"
#include "core/eval/scene_surfaces.hpp"
#include "core/io/input_limits.hpp"
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

// STEP / IGES: B-spline faces through OpenCASCADE (core/cad/cad_export.hpp).
int export_cad_file(const Arguments& a, const std::string& target, std::ostream& out) {
  if (a.value("--density")) throw UsageError("--density applies to mesh output only");
  CadExportOptions options;
  if (const auto t = a.value("--tolerance")) options.tolerance = tolerance_option(*t);
  options.scheme = parse_scheme_option(a.value("--scheme"));
  options.source = a.positional()[0];
  const Scene scene = load_input(options.source);
  out << cad_report_text(export_cad(scene, target, options));
  return kExitOk;
}

}  // namespace

int run_export(std::span<const std::string> args, std::ostream& out, std::ostream&) {
  const Arguments a(args, {"-o", "--density", "--scheme", "--tolerance"}, {});
  if (a.positional().size() != 1) throw UsageError("export takes exactly one input FILE");
  const auto target = a.value("-o");
  if (!target) throw UsageError("export needs -o OUT.{obj,ply,off,stl,step,stp,igs,iges}");
  if (cad_format_for(*target)) return export_cad_file(a, *target, out);
  if (a.value("--tolerance")) throw UsageError("--tolerance applies to STEP and IGES output only");
  const int density = a.integer("--density", 32, 1, kMaxDensity);
  const auto scheme = parse_scheme_option(a.value("--scheme"));
  mesh_format_for(*target);  // reject an unknown format before any work
  const std::string file = a.positional()[0];
  const Scene scene = load_input(file);
  check_work_limits(scene, density, file);
  TessellationCache cache;
  const SceneSurfaces surfaces = evaluate_scene(scene, density, scheme, cache, file);
  std::vector<SurfaceMesh> meshes;
  for (const SceneSurface& s : surfaces.surfaces)
    meshes.push_back(make_surface_mesh(*s.evaluator, s.name));
  for (std::size_t i = 0; i < scene.curves.size(); ++i)
    check_curve_finite(scene.curves[i], i, density, file);
  std::vector<CurvePolyline> polylines;
  if (mesh_format_for(*target) == MeshFormat::Obj)
    for (std::size_t i = 0; i < scene.curves.size(); ++i)
      polylines.push_back(curve_polyline(scene.curves[i], curve_name(scene.curves[i], i), density));
  export_meshes(meshes, *target, file, polylines);
  out << "wrote " << meshes.size() << " patch(es)";
  if (!polylines.empty()) out << " and " << polylines.size() << " curve(s)";
  out << " to " << *target << "\n";
  return kExitOk;
}

}  // namespace pl
