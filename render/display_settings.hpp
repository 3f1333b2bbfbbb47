// What to draw: one base mode plus overlays, and the parameters of each. Parsed from the CLI's
// "--mode mean+isophotes+control-net" syntax; the editor will set the same struct from its UI.
#pragma once

#include <optional>
#include <string>

#include "core/math/vec.hpp"
#include "render/color_map.hpp"

namespace pl {

enum class BaseMode { Shaded, Isophotes, Zebra, Curvature };

// Teeth longer than this many reference lengths (the automatic length at the reference
// curvature, times the user's multiplier) are cut to it: near a cusp the curvature grows
// without bound, and one tooth across the whole picture hides everything else. The envelope is
// capped the same way, so a flat top on it marks a capped stretch.
inline constexpr double kCombCap = 3.0;

struct DisplaySettings {
  BaseMode base = BaseMode::Shaded;
  CurvatureKind curvature = CurvatureKind::Mean;  // for BaseMode::Curvature

  // Overlays, combinable with any base mode.
  bool isophote_lines = false;  // implied by BaseMode::Isophotes
  // Zebra stripes are reflection lines already: isophote lines over them (black on black) are
  // left out unless asked for here ("zebra+isophotes" on the command line asks).
  bool isophotes_over_zebra = false;
  bool control_net = false;
  bool network_curves = false;
  bool borders = false;  // patch boundaries
  bool combs = false;    // curvature combs on the network curves and/or borders shown

  // Curvature combs: tooth length per unit curvature is comb_length (model units), or the
  // scene's automatic one (see automatic_comb_scale) when nullopt, times comb_scale. comb_teeth
  // is the number of tooth intervals per curve, used by whoever builds the DrawScene.
  double comb_scale = 1.0;
  std::optional<double> comb_length;
  int comb_teeth = 32;

  // Isophotes: lines where the angle between the normal and a light direction fixed in the model
  // is a multiple of 180 deg / count.
  int isophote_count = 18;
  double isophote_width_px = 1.6;
  Vec3 isophote_direction{0.3, -0.5, 0.81};  // model space; need not be unit

  // Zebra: `count` dark stripes per half turn of the reflected ray; width is the dark fraction.
  int zebra_count = 8;
  double zebra_width = 0.5;

  // Curvature: the range of the colour map (nullopt: automatic with percentile clipping) and
  // whether the colours are lit. Unlit ("flat") output is exactly the colour map.
  std::optional<ColorRange> range;
  double range_percentile = 98.0;
  bool curvature_lighting = true;

  bool transparent = false;  // clear to alpha 0 instead of the studio backdrop
};

// Whether the isophote lines are drawn over the base mode (always in the isophote mode).
bool shows_isophote_lines(const DisplaySettings& s);

// Parses "shaded", "isophotes", "zebra", "mean", "gaussian", "kmax", "kmin", "control-net",
// "network", "borders", "combs", combined with '+'. At most one of shaded/zebra/curvature is the
// base; "isophotes" is the base when alone and an overlay otherwise (over zebra too, when named
// with it). Throws std::invalid_argument
// with a message naming the offending token.
DisplaySettings parse_display_mode(const std::string& mode);

}  // namespace pl
