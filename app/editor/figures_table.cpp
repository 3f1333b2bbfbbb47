#include "app/editor/figures_table.hpp"

#include <imgui.h>

#include <cstdio>

#include "app/editor/logic/compare_layout.hpp"
#include "core/scene/network_edit.hpp"

namespace pl {

void draw_figures_table(const ViewRect& strip, const CompareFigures& figures, bool stale) {
  if (strip.height < 1) return;
  ImGui::SetNextWindowPos(ImVec2(float(strip.x), float(strip.y)));
  ImGui::SetNextWindowSize(ImVec2(float(strip.width), float(strip.height)));
  ImGui::Begin("##figures", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                   ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoBringToFrontOnFocus);
  const auto& result = figures.result();
  if (!result) {
    ImGui::TextDisabled(figures.error().empty() ? "Computing the figures of each scheme ..."
                                                : figures.error().c_str());
    ImGui::End();
    return;
  }
  char title[256];
  std::snprintf(title, sizeof title, "Quality figures at density %d, distances to %s%s",
                result->density, scheme_title(result->base).c_str(),
                stale ? "   (updating ...)" : "");
  ImGui::TextUnformatted(title);
  static const char* headers[] = {"face",    "scheme",  "G1 angle",  "boundary",
                                  "H range", "K range", "bending",   "grad H",
                                  "area",    "to base", "Msamples/s"};
  constexpr int kColumns = 11;
  if (ImGui::BeginTable("figures", kColumns,
                        ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV |
                            ImGuiTableFlags_ScrollY | ImGuiTableFlags_SizingStretchProp)) {
    ImGui::TableSetupScrollFreeze(0, 1);
    for (const char* h : headers) ImGui::TableSetupColumn(h);
    ImGui::TableHeadersRow();
    char b[96];
    auto cell = [&](const char* fmt, double a, double c = 0) {
      ImGui::TableNextColumn();
      std::snprintf(b, sizeof b, fmt, a, c);
      ImGui::TextUnformatted(b);
    };
    for (const FaceFigures& face : result->faces)
      for (const SchemeFigures& f : face.schemes) {
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::Text("%s (%d)", face.name.c_str(), face.sides);
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(scheme_title(f.scheme).c_str());
        if (!f.cannot_fill.empty()) {
          ImGui::TableNextColumn();
          ImGui::TextDisabled("cannot fill: %s", f.cannot_fill.c_str());
          continue;
        }
        cell("%.2e deg", f.max_normal_angle_deg);
        cell("%.2e", f.max_boundary_deviation);
        cell("[%.3g, %.3g]", f.mean[0], f.mean[1]);
        cell("[%.3g, %.3g]", f.gaussian[0], f.gaussian[1]);
        cell("%.5g", f.bending_energy);
        cell("%.4g", f.mean_curvature_gradient_energy);
        cell("%.5g", f.area);
        cell("%.3g", f.max_distance_to_base);
        cell("%.3g", f.msamples_per_s);
      }
    ImGui::EndTable();
  }
  ImGui::End();
}

}  // namespace pl
