// The Display section: render mode and its parameters, overlays, curvature combs, densities.
#include <imgui.h>

#include <algorithm>

#include "app/editor/side_panel.hpp"

namespace pl {

bool draw_display_section(const SidePanel& p) {
  DisplaySettings& d = p.model.prefs().display;
  static const char* modes[] = {"Shaded", "Isophotes", "Zebra", "Curvature"};
  int base = static_cast<int>(d.base);
  ImGui::SetNextItemWidth(-1);
  if (ImGui::Combo("##mode", &base, modes, 4)) d.base = static_cast<BaseMode>(base);
  if (d.base == BaseMode::Curvature) {
    static const char* kinds[] = {"Gaussian K", "Mean H", "k min", "k max"};
    int k = static_cast<int>(d.curvature);
    if (ImGui::Combo("Curvature", &k, kinds, 4)) d.curvature = static_cast<CurvatureKind>(k);
    bool fixed = d.range.has_value();
    if (ImGui::Checkbox("Fixed range", &fixed)) {
      if (fixed)
        d.range = p.range;
      else
        d.range.reset();
    }
    if (d.range) {
      float hi = float(d.range->hi);
      if (ImGui::DragFloat("+/- range", &hi, std::max(1e-4f, hi * 0.01f), 1e-6f, 1e6f, "%.4g"))
        d.range = ColorRange{-std::max(1e-9, double(hi)), std::max(1e-9, double(hi))};
    } else {
      float pc = float(d.range_percentile);
      if (ImGui::SliderFloat("Percentile", &pc, 50, 100, "%.1f %%")) d.range_percentile = pc;
    }
    ImGui::Checkbox("Lit colours", &d.curvature_lighting);
  }
  if (d.base == BaseMode::Zebra) {
    ImGui::SliderInt("Stripes", &d.zebra_count, 2, 60);
    float w = float(d.zebra_width);
    if (ImGui::SliderFloat("Dark fraction", &w, 0.05f, 0.95f)) d.zebra_width = w;
  }
  // The switch shows what is drawn in this mode (the isophote mode's lines are the mode itself).
  bool lines = isophote_switch(d);
  ImGui::BeginDisabled(d.base == BaseMode::Isophotes);
  if (ImGui::Checkbox(d.base == BaseMode::Zebra ? "Isophote lines over stripes" : "Isophote lines",
                      &lines))
    set_isophote_switch(d, lines);
  ImGui::EndDisabled();
  if (lines) {
    ImGui::SliderInt("Isophotes", &d.isophote_count, 2, 60);
    float w = float(d.isophote_width_px);
    if (ImGui::SliderFloat("Line width", &w, 0.5f, 5.0f, "%.1f px")) d.isophote_width_px = w;
  }
  ImGui::Checkbox("Control net", &d.control_net);
  ImGui::SameLine(ImGui::GetContentRegionAvail().x * 0.5f);
  ImGui::Checkbox("Curves", &d.network_curves);
  ImGui::Checkbox("Patch borders", &d.borders);
  ImGui::SameLine(ImGui::GetContentRegionAvail().x * 0.5f);
  ImGui::Checkbox("Probe", &p.model.prefs().show_probe);
  ImGui::Checkbox("Curvature combs", &d.combs);
  panel_tooltip(p,
                "Teeth of length proportional to the curvature, away from the centre of\n"
                "curvature, on the curves and borders shown (on the curves if neither is)");
  if (d.combs) {
    float scale = float(d.comb_scale);
    if (ImGui::SliderFloat("Comb scale", &scale, float(kMinCombScale), float(kMaxCombScale),
                           "%.2f x", ImGuiSliderFlags_Logarithmic))
      d.comb_scale = scale;
    panel_tooltip(p,
                  "Multiplies the automatic tooth length (the 90th-percentile curvature\n"
                  "gets 6 % of the scene diagonal; teeth are capped at 3 times that)");
    // A new count resamples the combs only (the views follow it each frame, no re-evaluation).
    ImGui::SliderInt("Comb teeth", &d.comb_teeth, kMinCombTeeth, kMaxCombTeeth);
    panel_tooltip(p, "Teeth per curve");
  }
  // The interface's size: the monitor's content scale unless the user picks one (applied from
  // the next frame, kept in the preferences).
  static const double kScales[] = {0, 1.0, 1.25, 1.5, 1.75, 2.0};
  static const char* kScaleNames[] = {"Auto (monitor)", "100 %", "125 %",
                                      "150 %",          "175 %", "200 %"};
  int scale = 0;
  for (int i = 0; i < 6; ++i)
    if (p.model.prefs().ui_scale == kScales[i]) scale = i;
  if (ImGui::Combo("Interface", &scale, kScaleNames, 6)) p.model.prefs().ui_scale = kScales[scale];
  int densities[2] = {p.model.prefs().coarse_density, p.model.prefs().fine_density};
  if (ImGui::SliderInt2("Density", densities, 4, 96)) {
    p.model.prefs().coarse_density = densities[0];
    p.model.prefs().fine_density = densities[1];
  }
  const bool rebuild = ImGui::IsItemDeactivatedAfterEdit();
  panel_tooltip(p, "Samples per boundary curve while dragging / at rest");
  return rebuild;
}

}  // namespace pl
