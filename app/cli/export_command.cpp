#include "app/cli/arguments.hpp"
#include "app/cli/cli.hpp"
#include "app/cli/commands.hpp"
#include "app/cli/load_input.hpp"
#include "app/cli/work_limits.hpp"
#include "core/eval/scene_surfaces.hpp"
#include "core/io/input_limits.hpp"
#include "core/mesh/mesh_export.hpp"

namespace pl {

int run_export(std::span<const std::string> args, std::ostream& out, std::ostream&) {
  const Arguments a(args, {"-o", "--density", "--scheme"}, {});
  if (a.positional().size() != 1) throw UsageError("export takes exactly one input FILE");
  const auto target = a.value("-o");
  if (!target) throw UsageError("export needs -o OUT.{obj,ply,off,stl}");
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
  export_meshes(meshes, *target, file);
  out << "wrote " << meshes.size() << " patch(es) to " << *target << "\n";
  return kExitOk;
}

}  // namespace pl
