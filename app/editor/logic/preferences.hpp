// The editor's preferences, kept in $XDG_CONFIG_HOME/patchlab/preferences.ini as "key = value"
// lines. Unknown keys and malformed values are ignored (a newer or hand-edited file never stops
// the editor). GUI-free and unit-tested.
#pragma once

#include <filesystem>
#include <string>

#include "render/display_settings.hpp"

namespace pl {

struct Preferences {
  DisplaySettings display;
  int fine_density = 48;    // after a drag settles
  int coarse_density = 16;  // while dragging
  double ui_scale = 0;      // 0: from the monitor's content scale
  bool show_probe = true;
  // The Continuity panel warns only about edges whose normal angle exceeds this (degrees).
  double continuity_threshold_deg = 0.1;
  int screenshot_width = 1920, screenshot_height = 1080;
  bool screenshot_transparent = false;
  std::string last_directory;
  // The comparison's panes (compare_layout.hpp): one scheme keyword per pane, and the base.
  std::string compare_schemes = "gregory,gb";
  std::string compare_base = "gregory";
};

// The ranges of the comb controls (Display panel sliders, accepted preference values).
inline constexpr double kMinCombScale = 0.05, kMaxCombScale = 20.0;
inline constexpr int kMinCombTeeth = 2, kMaxCombTeeth = 200;
// The continuity warning threshold accepted from the panel or the file (degrees).
inline constexpr double kMinContinuityThresholdDeg = 1e-6, kMaxContinuityThresholdDeg = 90.0;

// The isophote mode with the control net, curves and borders shown; no isophote lines over
// the other modes (Shaded reads as shading, zebra stripes as reflections).
Preferences default_preferences();
std::string preferences_to_text(const Preferences& p);
Preferences preferences_from_text(const std::string& text);

// Missing or unreadable file: the defaults.
Preferences load_preferences(const std::filesystem::path& file);
// The Display panel's "Isophote lines" switch for the mode shown: what is drawn (always on in the
// isophote mode, where the lines are the mode; over zebra stripes only when asked for there).
bool isophote_switch(const DisplaySettings& d);
void set_isophote_switch(DisplaySettings& d, bool on);

// Atomic; returns false (and keeps the old file) on failure.
bool save_preferences(const std::filesystem::path& file, const Preferences& p);

}  // namespace pl
