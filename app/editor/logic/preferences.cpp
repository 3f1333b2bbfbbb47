#include "app/editor/logic/preferences.hpp"

#include <algorithm>
#include <charconv>
#include <fstream>
#include <sstream>

#include "core/io/atomic_file.hpp"

namespace pl {

namespace {

const char* base_name(BaseMode m) {
  switch (m) {
    case BaseMode::Shaded:
      return "shaded";
    case BaseMode::Isophotes:
      return "isophotes";
    case BaseMode::Zebra:
      return "zebra";
    case BaseMode::Curvature:
      return "curvature";
  }
  return "shaded";
}

bool parse_double(const std::string& s, double& out) {
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
  return ec == std::errc() && end == s.data() + s.size();
}

bool parse_int(const std::string& s, int& out, int lo, int hi) {
  int v = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size() || v < lo || v > hi) return false;
  out = v;
  return true;
}

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  const auto e = s.find_last_not_of(" \t\r");
  return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}

}  // namespace

Preferences default_preferences() {
  Preferences p;
  p.display.base = BaseMode::Isophotes;
  p.display.control_net = true;
  p.display.network_curves = true;
  p.display.borders = true;
  return p;
}

bool isophote_switch(const DisplaySettings& d) {
  return shows_isophote_lines(d);
}

void set_isophote_switch(DisplaySettings& d, bool on) {
  switch (d.base) {
    case BaseMode::Isophotes:
      return;  // the lines are the mode
    case BaseMode::Zebra:
      d.isophotes_over_zebra = on;
      if (on) d.isophote_lines = true;
      return;
    default:
      d.isophote_lines = on;
  }
}

std::string preferences_to_text(const Preferences& p) {
  std::ostringstream o;
  o.precision(17);
  const DisplaySettings& d = p.display;
  o << "# PatchLab editor preferences\n"
    << "base = " << base_name(d.base) << "\n"
    << "curvature = " << curvature_name(d.curvature) << "\n"
    << "isophote_lines = " << d.isophote_lines << "\n"
    << "isophotes_over_zebra = " << d.isophotes_over_zebra << "\n"
    << "control_net = " << d.control_net << "\n"
    << "network_curves = " << d.network_curves << "\n"
    << "borders = " << d.borders << "\n"
    << "combs = " << d.combs << "\n"
    << "comb_scale = " << d.comb_scale << "\n"
    << "comb_teeth = " << d.comb_teeth << "\n"
    << "isophote_count = " << d.isophote_count << "\n"
    << "zebra_count = " << d.zebra_count << "\n"
    << "zebra_width = " << d.zebra_width << "\n"
    << "range_percentile = " << d.range_percentile << "\n"
    << "curvature_lighting = " << d.curvature_lighting << "\n"
    << "fine_density = " << p.fine_density << "\n"
    << "coarse_density = " << p.coarse_density << "\n"
    << "ui_scale = " << p.ui_scale << "\n"
    << "show_probe = " << p.show_probe << "\n"
    << "continuity_threshold_deg = " << p.continuity_threshold_deg << "\n"
    << "screenshot_width = " << p.screenshot_width << "\n"
    << "screenshot_height = " << p.screenshot_height << "\n"
    << "screenshot_transparent = " << p.screenshot_transparent << "\n"
    << "last_directory = " << p.last_directory << "\n"
    << "compare_schemes = " << p.compare_schemes << "\n"
    << "compare_base = " << p.compare_base << "\n";
  return o.str();
}

Preferences preferences_from_text(const std::string& text) {
  Preferences p = default_preferences();
  DisplaySettings& d = p.display;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    const auto eq = line.find('=');
    if (eq == std::string::npos) continue;
    const std::string key = trim(line.substr(0, eq)), value = trim(line.substr(eq + 1));
    int i = 0;
    double x = 0;
    auto flag = [&](bool& out) {
      if (value == "0" || value == "1") out = value == "1";
    };
    if (key == "base") {
      for (BaseMode m :
           {BaseMode::Shaded, BaseMode::Isophotes, BaseMode::Zebra, BaseMode::Curvature})
        if (value == base_name(m)) d.base = m;
    } else if (key == "curvature") {
      for (CurvatureKind k :
           {CurvatureKind::Gaussian, CurvatureKind::Mean, CurvatureKind::Kmin, CurvatureKind::Kmax})
        if (value == curvature_name(k)) d.curvature = k;
    } else if (key == "isophote_lines") {
      flag(d.isophote_lines);
    } else if (key == "isophotes_over_zebra") {
      flag(d.isophotes_over_zebra);
    } else if (key == "control_net") {
      flag(d.control_net);
    } else if (key == "network_curves") {
      flag(d.network_curves);
    } else if (key == "borders") {
      flag(d.borders);
    } else if (key == "combs") {
      flag(d.combs);
    } else if (key == "comb_scale" && parse_double(value, x) && x >= kMinCombScale &&
               x <= kMaxCombScale) {
      d.comb_scale = x;
    } else if (key == "comb_teeth" && parse_int(value, i, kMinCombTeeth, kMaxCombTeeth)) {
      d.comb_teeth = i;
    } else if (key == "isophote_count" && parse_int(value, i, 1, 200)) {
      d.isophote_count = i;
    } else if (key == "zebra_count" && parse_int(value, i, 1, 200)) {
      d.zebra_count = i;
    } else if (key == "zebra_width" && parse_double(value, x) && x > 0 && x < 1) {
      d.zebra_width = x;
    } else if (key == "range_percentile" && parse_double(value, x) && x > 0 && x <= 100) {
      d.range_percentile = x;
    } else if (key == "curvature_lighting") {
      flag(d.curvature_lighting);
    } else if (key == "fine_density" && parse_int(value, i, 2, 256)) {
      p.fine_density = i;
    } else if (key == "coarse_density" && parse_int(value, i, 2, 256)) {
      p.coarse_density = i;
    } else if (key == "ui_scale" && parse_double(value, x) && x >= 0 && x <= 4) {
      p.ui_scale = x;
    } else if (key == "show_probe") {
      flag(p.show_probe);
    } else if (key == "continuity_threshold_deg" && parse_double(value, x) &&
               x >= kMinContinuityThresholdDeg && x <= kMaxContinuityThresholdDeg) {
      p.continuity_threshold_deg = x;
    } else if (key == "screenshot_width" && parse_int(value, i, 16, 8192)) {
      p.screenshot_width = i;
    } else if (key == "screenshot_height" && parse_int(value, i, 16, 8192)) {
      p.screenshot_height = i;
    } else if (key == "screenshot_transparent") {
      flag(p.screenshot_transparent);
    } else if (key == "last_directory") {
      p.last_directory = value;
    } else if (key == "compare_schemes") {
      p.compare_schemes = value;  // checked where it is read (compare_setup_from)
    } else if (key == "compare_base") {
      p.compare_base = value;
    }
  }
  return p;
}

Preferences load_preferences(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) return default_preferences();
  std::stringstream s;
  s << in.rdbuf();
  return preferences_from_text(s.str());
}

bool save_preferences(const std::filesystem::path& file, const Preferences& p) {
  try {
    std::error_code ec;
    std::filesystem::create_directories(file.parent_path(), ec);
    write_file_atomically(file, preferences_to_text(p));
    return true;
  } catch (const std::exception&) {
    return false;
  }
}

}  // namespace pl
