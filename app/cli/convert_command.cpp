// `patchlab convert IN -o OUT`: .gbp <-> .json scene. A scene becomes a .gbp only if it holds
// exactly one explicit gb patch and nothing else (a .gbp stores one patch and no names).
#include "app/cli/arguments.hpp"
#include "app/cli/cli.hpp"
#include "app/cli/commands.hpp"
#include "app/cli/load_input.hpp"
#include "core/base/data_error.hpp"
#include "core/io/gbp_io.hpp"
#include "core/io/scene_io.hpp"
#include "core/patch/gb/gb_patch.hpp"

namespace pl {

namespace {

const GBPatch& single_gb_patch(const Scene& scene, const std::string& file) {
  if (scene.network)
    throw DataError(file, "network",
                    "a .gbp holds exactly one gb patch; this scene has a curve network");
  if (scene.patches.size() != 1)
    throw DataError(file, "patches",
                    "a .gbp holds exactly one gb patch; this scene has " +
                        std::to_string(scene.patches.size()) + " explicit patches");
  const auto* gb = dynamic_cast<const GBPatch*>(scene.patches[0].patch.get());
  if (!gb)
    throw DataError(file, "patches[0]",
                    "a .gbp holds a gb patch; this patch is of type \"" +
                        scene.patches[0].patch->type() + "\"");
  return *gb;
}

}  // namespace

int run_convert(std::span<const std::string> args, std::ostream& out, std::ostream&) {
  const Arguments a(args, {"-o"}, {});
  if (a.positional().size() != 1) throw UsageError("convert takes exactly one input file IN");
  const auto target = a.value("-o");
  if (!target) throw UsageError("convert needs -o OUT.{gbp,json}");
  const std::string ext = std::filesystem::path(*target).extension().string();
  if (ext != ".gbp" && ext != ".json")
    throw UsageError("convert writes .gbp or .json, not \"" + ext + "\"");
  const std::string file = a.positional()[0];
  const Scene scene = load_input(file);
  if (ext == ".gbp")
    write_gbp(*target, single_gb_patch(scene, file));
  else
    write_scene(*target, scene);
  out << "wrote " << *target << "\n";
  return kExitOk;
}

}  // namespace pl
