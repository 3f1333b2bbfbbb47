#include "app/editor/logic/editor_paths.hpp"

#include <algorithm>
#include <cstdlib>
#include <system_error>

namespace pl {

namespace fs = std::filesystem;

std::optional<fs::path> xdg_dir(const char* xdg_value, const char* home,
                                const std::string& home_fallback) {
  // The spec says relative XDG values are invalid and must be ignored.
  if (xdg_value && *xdg_value && fs::path(xdg_value).is_absolute())
    return fs::path(xdg_value) / "patchlab";
  if (home && *home && fs::path(home).is_absolute())
    return fs::path(home) / home_fallback / "patchlab";
  return std::nullopt;
}

std::optional<fs::path> config_dir() {
  return xdg_dir(std::getenv("XDG_CONFIG_HOME"), std::getenv("HOME"), ".config");
}

std::optional<fs::path> state_dir() {
  return xdg_dir(std::getenv("XDG_STATE_HOME"), std::getenv("HOME"), ".local/state");
}

namespace {

// The nearest assets/default.json above the executable's directory (a moved build tree).
std::optional<fs::path> default_scene_above(const fs::path& executable) {
  std::error_code ec;
  if (executable.empty()) return std::nullopt;
  for (fs::path dir = executable.parent_path(); !dir.empty(); dir = dir.parent_path()) {
    const fs::path candidate = dir / "assets" / "default.json";
    if (fs::is_regular_file(candidate, ec)) return candidate;
    if (dir == dir.parent_path()) break;
  }
  return std::nullopt;
}

}  // namespace

std::optional<fs::path> default_scene_path(const fs::path& executable) {
#ifdef PATCHLAB_ASSETS_DIR
  std::error_code ec;
  const fs::path built = fs::path(PATCHLAB_ASSETS_DIR) / "default.json";
  if (fs::is_regular_file(built, ec)) return built;
#endif
  return default_scene_above(executable);
}

std::vector<fs::path> shipped_scene_dirs(const fs::path& executable) {
  std::vector<fs::path> dirs;
#ifdef PATCHLAB_ASSETS_DIR
  dirs.emplace_back(PATCHLAB_ASSETS_DIR);
#endif
  if (const auto found = default_scene_above(executable)) {
    const fs::path dir = found->parent_path();
    if (std::find(dirs.begin(), dirs.end(), dir) == dirs.end()) dirs.push_back(dir);
  }
  return dirs;
}

fs::path executable_path() {
  std::error_code ec;
  fs::path p = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::path() : p;
}

}  // namespace pl
