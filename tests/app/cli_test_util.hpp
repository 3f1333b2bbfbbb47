// Runs the CLI in-process on files in a fresh temporary directory.
#pragma once

#include <signal.h>
#include <sys/types.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "app/cli/cli.hpp"

namespace pl::test {

class TempDir {
 public:
  TempDir() {
    std::random_device rd;
    path_ = std::filesystem::temp_directory_path() / ("patchlab-test-" + std::to_string(rd()));
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  std::filesystem::path file(const std::string& name, const std::string& content) const {
    const auto p = path_ / name;
    std::ofstream(p) << content;
    return p;
  }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

 private:
  std::filesystem::path path_;
};

struct CliResult {
  int code;
  std::string out, err;
};

inline CliResult cli(std::vector<std::string> args) {
  std::ostringstream out, err;
  const int code = run_cli(args, out, err);
  return {code, out.str(), err.str()};
}

inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Every point scaled by s: [x, y, z] arrays anywhere in the document.
inline nlohmann::json scaled(nlohmann::json j, double s) {
  if (j.is_array() && j.size() == 3 && j[0].is_number() && j[1].is_number() && j[2].is_number())
    return {j[0].get<double>() * s, j[1].get<double>() * s, j[2].get<double>() * s};
  if (j.is_array() || j.is_object())
    for (auto& v : j) v = scaled(v, s);
  return j;
}

#ifdef PATCHLAB_BINARY
// The binary writing a big PLY of the default scene to target (in a directory of its own),
// started and watched until its temporary file appears there. `default_signal`: a signal set back
// to its default action in the child (a job started in the background of a script inherits
// SIGINT ignored).
struct SlowWriter {
  pid_t pid;
  bool writing;  // the temporary file appeared
};
inline SlowWriter start_slow_export(const std::filesystem::path& target, int default_signal = 0) {
  const pid_t child = fork();
  if (child == 0) {
    if (default_signal) signal(default_signal, SIG_DFL);
    execl(PATCHLAB_BINARY, PATCHLAB_BINARY, "export", PATCHLAB_SOURCE_DIR "/assets/default.json",
          "-o", target.c_str(), "--density", "200", static_cast<char*>(nullptr));
    _exit(127);
  }
  // Built by appends: GCC 12 reports a false -Wrestrict for "literal" + std::string at -O3.
  std::string prefix = ".";
  prefix += target.filename().string();
  prefix += ".tmp";
  bool seen = false;
  // Up to 5 minutes: the sanitizer build evaluates slowly before it starts writing.
  for (int i = 0; i < 30000 && !seen; ++i) {
    for (const auto& e : std::filesystem::directory_iterator(target.parent_path()))
      seen = seen || e.path().filename().string().rfind(prefix, 0) == 0;
    if (!seen) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return {child, seen};
}
#endif

}  // namespace pl::test
