// `patchlab convert IN -o OUT`: .gbp <-> .json scene. A scene becomes a .gbp only if it holds
// exactly one explicit gb patch and nothing else (a .gbp stores one patch and no names).
#include "app/cli/arguments.hpp"
#include "app/cli/cli.hpp"
#include "app/cli/commands.hpp"
#include "app/cli/load_input.hpp"
#include "app/document/scene_file.hpp"
#include "core/base/data_error.hpp"
#include "core/io/gbp_io.hpp"
#include "core/io/json_node.hpp"
#include "core/io/scene_io.hpp"
#include "core/patch/gb/gb_patch.hpp"

namespace pl {

int run_convert(std::span<const std::string> args, std::ostream& out, std::ostream&) {
  const Arguments a(args, {"-o"}, {});
  if (a.positional().size() != 1) throw UsageError("convert takes exactly one input file IN");
  const auto target = a.value("-o");
  if (!target) throw UsageError("convert needs -o OUT.{gbp,json}");
  const std::string ext = std::filesystem::path(*target).extension().string();
  if (ext != ".gbp" && ext != ".json")
    throw UsageError("convert writes .gbp or .json, not \"" + ext + "\"");
  const std::string file = a.positional()[0];
  check_input_name(file);
  const Scene scene = load_scene_file(file);
  if (ext == ".gbp")
    write_gbp(*target, single_gb_patch(scene, file));
  else
    write_scene(*target, scene);
  out << "wrote " << printable(*target) << "\n";
  return kExitOk;
}

}  // namespace pl
