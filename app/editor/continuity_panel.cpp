// The Continuity section: per shared edge the G0 gap, G1 normal angle and mean-curvature jump of
// the fine surfaces; a row click selects the edge (drawn in the view like any selection).
#include <imgui.h>

#include <algorithm>
#include <cstdio>

#include "app/editor/side_panel.hpp"

namespace pl {

void draw_continuity_section(const SidePanel& p) {
  const SceneReport& report = p.continuity.report();
  if (report.edges.empty()) {
    ImGui::TextDisabled("No shared edges.");
    return;
  }
  const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV |
                                ImGuiTableFlags_ScrollY | ImGuiTableFlags_SizingStretchProp;
  const float h = std::min(ImGui::GetTextLineHeightWithSpacing() * (report.edges.size() + 1.6f),
                           ImGui::GetContentRegionAvail().y);
  if (!ImGui::BeginTable("continuity", 4, flags, ImVec2(0, h))) return;
  ImGui::TableSetupScrollFreeze(0, 1);
  ImGui::TableSetupColumn("edge");
  ImGui::TableSetupColumn("G0 gap");
  ImGui::TableSetupColumn("G1 deg");
  ImGui::TableSetupColumn("H jump");
  ImGui::TableHeadersRow();
  for (int i = 0; i < int(report.edges.size()); ++i) {
    const EdgeReport& e = report.edges[i];
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    const bool worst = i == p.continuity.worst();
    char label[64];
    std::snprintf(label, sizeof label, "%s%d (%d|%d)", worst ? "! " : "", e.edge, e.faces[0],
                  e.faces[1]);
    if (worst) ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.42f, 1));
    const SelectionItem item = SelectionItem::edge(e.edge);
    if (ImGui::Selectable(label, p.selection.contains(item), ImGuiSelectableFlags_SpanAllColumns))
      p.selection.set({item});
    ImGui::TableNextColumn();
    ImGui::Text("%.2e", e.max_gap);
    ImGui::TableNextColumn();
    ImGui::Text("%.3f", e.max_normal_angle_deg);
    ImGui::TableNextColumn();
    ImGui::Text("%.3g", e.max_mean_curvature_jump);
    if (worst) ImGui::PopStyleColor();
  }
  ImGui::EndTable();
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
  ImGui::TextWrapped("Red: the edge with the largest normal angle. A row selects its edge.");
  ImGui::PopStyleColor();
}

}  // namespace pl
