// `patchlab gbnet IN.gbp -o OUT.gbp [--defaults boundary|ring1] [--elevate K]`: fills the control
// points of a GB patch that a designer did not place with their default positions
// (core/patch/gb/default_net.hpp) and/or elevates its degree K times (core/patch/gb/elevation.hpp).
// A .gbp has no "unplaced" marker, so --defaults names what is kept: the boundary alone, or the
// boundary and the cross-boundary ring; every other point, C_0 included, is recomputed.
#include <string>

#include "app/cli/arguments.hpp"
#include "app/cli/cli.hpp"
#include "app/cli/commands.hpp"
#include "core/base/data_error.hpp"
#include "core/io/gbp_io.hpp"
#include "core/io/json_node.hpp"
#include "core/patch/gb/default_net.hpp"
#include "core/patch/gb/elevation.hpp"

namespace pl {

int run_gbnet(std::span<const std::string> args, std::ostream& out, std::ostream&) {
  const Arguments a(args, {"-o", "--defaults", "--elevate"}, {});
  if (a.positional().size() != 1) throw UsageError("gbnet takes exactly one input file IN.gbp");
  const auto target = a.value("-o");
  if (!target) throw UsageError("gbnet needs -o OUT.gbp");
  if (std::filesystem::path(*target).extension() != ".gbp")
    throw UsageError("gbnet writes a .gbp, not \"" + *target + "\"");
  const std::string file = a.positional()[0];
  if (std::filesystem::path(file).extension() != ".gbp")
    throw UsageError("gbnet reads a .gbp, not \"" + file + "\"");
  const auto defaults = a.value("--defaults");
  if (defaults && *defaults != "boundary" && *defaults != "ring1")
    throw UsageError("--defaults takes boundary or ring1, got \"" + *defaults + "\"");
  const int elevate = a.integer("--elevate", 0, 1, GBPatch::kMaxDegree);
  if (!defaults && elevate == 0) throw UsageError("gbnet needs --defaults and/or --elevate K");

  GBPatch patch = read_gbp(file);
  // Checked before any work: gb_elevate takes degrees 2 .. kMaxDegree - 1, and the defaults keep
  // the degree, so the file's degree decides.
  const int d = patch.degree();
  if (elevate > 0 && (d < 2 || d + elevate > GBPatch::kMaxDegree))
    throw DataError(file, "",
                    "degree " + std::to_string(d) + " cannot be elevated " +
                        std::to_string(elevate) + " times (degrees 2.." +
                        std::to_string(GBPatch::kMaxDegree - 1) + " elevate, up to degree " +
                        std::to_string(GBPatch::kMaxDegree) + ")");
  if (defaults) patch = gb_default_net(patch, *defaults == "boundary" ? 1 : 2);
  for (int e = 0; e < elevate; ++e) patch = gb_elevate(patch);
  write_gbp(*target, patch);
  out << "wrote " << printable(*target) << " (" << patch.sides() << " sides, degree "
      << patch.degree() << ")\n";
  return kExitOk;
}

}  // namespace pl
