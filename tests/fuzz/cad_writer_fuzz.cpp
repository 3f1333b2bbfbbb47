// libFuzzer target: the STEP/IGES writer. Byte 0 picks the format (even: STEP, odd: IGES); the
// rest is a scene. What the reader accepts is exported as `patchlab export -o X.step` does
// (the fits, OpenCASCADE's faces and sewing, the translator, the atomic write) and, if the export
// succeeds, the file is read back by OpenCASCADE's reader. A DataError at either step is a
// correct answer; the file written by a successful export must read back with every face the
// report names (STEP keeps them one to one). Fits get a smaller work bound than the CLI's
// (a fit that reaches it is refused in the same way), so that one input stays well under
// libFuzzer's timeout.
#include <unistd.h>

#include <filesystem>

#include "core/base/data_error.hpp"
#include "core/cad/cad_export.hpp"
#include "core/cad/occt_io.hpp"
#include "core/io/scene_io.hpp"
#include "fuzz_common.hpp"

namespace {

const std::filesystem::path& work_dir() {
  static const std::filesystem::path dir = [] {
    auto d = std::filesystem::temp_directory_path() /
             ("patchlab-cad-fuzz-" + std::to_string(::getpid()));
    std::filesystem::create_directories(d);
    return d;
  }();
  return dir;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const bool step = data[0] % 2 == 0;
  const std::filesystem::path file = work_dir() / (step ? "out.step" : "out.igs");
  std::filesystem::remove(file);
  pl::CadExportReport report;
  try {
    const pl::Scene scene = pl::parse_scene(pl::fuzz::text(data + 1, size - 1), "fuzz.json");
    pl::CadExportOptions o;
    o.source = "fuzz.json";
    o.max_fit_work = std::size_t(1) << 16;
    o.time_limit_s = 30;
    report = pl::export_cad(scene, file, o);
  } catch (const pl::DataError&) {
    // Refused with a located message: correct, and nothing may be left at the target.
    if (std::filesystem::exists(file)) __builtin_trap();
    return 0;
  }
  // Written: OpenCASCADE reads it back (any exception, a DataError included, is a finding).
  const pl::CadFile back =
      pl::read_cad_file(file, step ? pl::CadFormat::Step : pl::CadFormat::Iges);
  if (step && back.faces.size() != report.faces.size()) __builtin_trap();
  return 0;
}
