#include "app/cli/cli.hpp"

#include <array>
#include <csignal>
#include <exception>

#include "app/cli/arguments.hpp"
#include "app/cli/commands.hpp"
#include "app/cli/progress_line.hpp"
#include "app/cli/stop_signals.hpp"
#include "core/base/data_error.hpp"
#include "core/io/json_node.hpp"

namespace pl {

std::span<const Command> commands() {
  static const std::array table{
      Command{"export",
              "FILE -o OUT.{obj,ply,off,stl} [--density N] [--scheme S]\n"
              "                       FILE -o OUT.{step,stp,igs,iges} [--tolerance T] "
              "[--scheme S]",
              run_export},
      Command{"analyze", "FILE [--density N] [--scheme S] [--json]", run_analyze},
      Command{"compare",
              "FILE [--schemes S,S,...] [--base S] [--faces F,F,...] [--density N] [--json]",
              run_compare},
      Command{"convert", "IN -o OUT  (.gbp <-> .json scene)", run_convert},
      Command{"render",
              "FILE -o OUT.png [--size WxH] [--mode MODE] [--view VIEW] [--compare [--schemes "
              "S,S,...]] [--transparent] [--density N]",
              run_render},
      Command{"gbnet", "IN.gbp -o OUT.gbp [--defaults boundary|ring1] [--elevate K]", run_gbnet},
      Command{"sample", "cube-sphere -o OUT.json [--cells K] [--scheme auto|S]", run_sample},
  };
  return table;
}

namespace {

void print_usage(std::ostream& os) {
  os << "usage: patchlab [FILE]\n";
  for (const Command& c : commands()) os << "       patchlab " << c.name << " " << c.usage << "\n";
  os << "       patchlab --help | --version\n";
}

void print_help(std::ostream& os) {
  os << "PatchLab " PATCHLAB_VERSION
        " - Gregory and Generalized Bézier patches over curve networks.\n\n";
  print_usage(os);
  os << "\nFILE is a scene (.json, see docs/scene-format.md) or a GB net (.gbp, see\n"
        "docs/gbp-format.md); the commands and their output: docs/cli.md.\n"
        "  --density N   samples per boundary curve (default 32)\n"
        "  --scheme S    fill network faces with S: gregory (3- and 4-sided faces), gb,\n"
        "                side-based, corner-based, generalized-coons, composite-ribbon,\n"
        "                midpoint, midpoint-coons or elastic (these seven: convex faces)\n"
        "Exit status: 0 success, 1 bad input (message names file and place), 2 wrong usage\n"
        "(what the command line alone shows: options, values, file name extensions).\n";
}

}  // namespace

int run_cli(std::span<const std::string> args, std::ostream& out, std::ostream& err) {
  // Past a file size limit (ulimit -f) a write then fails with EFBIG, which is reported with the
  // target's name, instead of SIGXFSZ killing the process mid-write.
  std::signal(SIGXFSZ, SIG_IGN);
  // Stopped by SIGTERM or SIGINT, a command removes its temporary file as it does on an error.
  remove_temporaries_on_stop_signals();
  if (!args.empty() && (args[0] == "--help" || args[0] == "-h")) {
    print_help(out);
    return kExitOk;
  }
  if (!args.empty() && args[0] == "--version") {
    out << "patchlab " PATCHLAB_VERSION "\n";
    return kExitOk;
  }
  try {
    if (args.empty() || args[0].empty() || args[0][0] == '-' ||
        (args.size() == 1 && args[0].find('.') != std::string::npos)) {
      throw UsageError("the editor is not part of this build yet; use a sub-command");
    }
    for (const Command& c : commands())
      if (args[0] == c.name) {
        // Erased before anything below reports an error.
        const ProgressLine progress("patchlab " + std::string(c.name));
        return c.run(args.subspan(1), out, err);
      }
    throw UsageError("unknown command \"" + args[0] + "\"");
  } catch (const UsageError& e) {
    // Every message is one line: file names and quoted arguments with control characters (a
    // newline in a file name) are printed escaped.
    err << "patchlab: " << printable(e.what()) << "\n";
    print_usage(err);
    return kExitUsage;
  } catch (const DataError& e) {
    err << "patchlab: " << printable(e.what()) << "\n";
    return kExitBadInput;
  } catch (const std::bad_alloc&) {
    err << "patchlab: out of memory (try a smaller --density)\n";
    return kExitBadInput;
  }
}

}  // namespace pl
