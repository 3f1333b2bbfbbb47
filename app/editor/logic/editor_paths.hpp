// Where the editor finds its default scene and keeps its preferences and window layout. GUI-free
// so the rules are unit-tested; nothing here ever points at the working directory.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace pl {

// The XDG base directory rule: $XDG_*_HOME when set to an absolute path, else $HOME/<fallback>.
// nullopt when neither gives an absolute path (then the editor keeps no files at all).
std::optional<std::filesystem::path> xdg_dir(const char* xdg_value, const char* home,
                                             const std::string& home_fallback);

// $XDG_CONFIG_HOME/patchlab (preferences) and $XDG_STATE_HOME/patchlab (imgui layout, recent
// files), from the process environment.
std::optional<std::filesystem::path> config_dir();
std::optional<std::filesystem::path> state_dir();

// assets/default.json: next to the sources this binary was built from, else found by walking up
// from the executable's directory (a moved build tree). nullopt when neither exists.
std::optional<std::filesystem::path> default_scene_path(const std::filesystem::path& executable);

// The folders holding the scenes shipped with PatchLab (the sources' assets folder, and the one
// found from the executable when it differs): the editor opens their scenes as untitled copies
// and never writes into them. The build installs nothing, so there is no other copy.
std::vector<std::filesystem::path> shipped_scene_dirs(const std::filesystem::path& executable);

// The running executable (/proc/self/exe), or empty when unknown.
std::filesystem::path executable_path();

}  // namespace pl
