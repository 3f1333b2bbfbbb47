// The Continuity section: the warning threshold, then per filling (the scene's own, or the
// comparison's Gregory and GB fillings, each labelled) a one-line verdict, per shared edge the
// G0 gap, G1 normal angle and mean-curvature jump of the fine surfaces, and the vertices whose
// end tangents were projected into their tangent plane. Edges over the threshold are marked and
// the worst one is drawn in the highlight colour in its view; a row click selects its edge. Then
// the joints of the free curves (an end on another curve's end or start) with their G0/G1/G2
// class, gap, tangent angle and curvature jump.
#include <imgui.h>

#include <algorithm>
#include <cstdio>

#include "app/editor/side_panel.hpp"
#include "render/palette.hpp"

namespace pl {

namespace {

ImVec4 highlight() {
  const Rgb c = palette::kHighlight;
  return ImVec4(c[0], c[1], c[2], 1);
}

void draw_filling(const SidePanel& p, const ContinuityMonitor::Filling& f, std::size_t index,
                  double threshold) {
  const SceneReport& report = f.report;
  const std::vector<int> over = p.model.continuity().warnings(index, threshold);
  if (!f.label.empty()) {
    ImGui::Separator();
    ImGui::TextUnformatted(f.label.c_str());
  }
  if (report.edges.empty()) {
    ImGui::TextDisabled("No shared edges.");
  } else if (over.empty()) {
    ImGui::TextWrapped("No edge above %.3g deg (largest %.3g deg).", threshold,
                       report.edges[f.worst].max_normal_angle_deg);
  } else {
    ImGui::PushStyleColor(ImGuiCol_Text, highlight());
    ImGui::TextWrapped("! %zu edge%s above %.3g deg (largest %.3g deg, edge %d).", over.size(),
                       over.size() == 1 ? "" : "s", threshold,
                       report.edges[over[0]].max_normal_angle_deg, report.edges[over[0]].edge);
    ImGui::PopStyleColor();
  }
  if (!report.edges.empty()) {
    const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV |
                                  ImGuiTableFlags_ScrollY | ImGuiTableFlags_SizingStretchProp;
    // At most about ten rows each: two fillings share the panel in the comparison.
    const float rows = std::min<float>(float(report.edges.size()), 10.0f);
    const float h = ImGui::GetTextLineHeightWithSpacing() * (rows + 1.6f);
    const std::string id = "continuity" + std::to_string(index);
    if (ImGui::BeginTable(id.c_str(), 4, flags, ImVec2(0, h))) {
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
        const bool warn = e.max_normal_angle_deg > threshold;
        char label[64];
        std::snprintf(label, sizeof label, "%s%d (%d|%d)##%zu", warn ? "! " : "", e.edge,
                      e.faces[0], e.faces[1], index);
        if (warn) ImGui::PushStyleColor(ImGuiCol_Text, highlight());
        const SelectionItem item = SelectionItem::edge(e.edge);
        if (ImGui::Selectable(label, p.model.selection().contains(item),
                              ImGuiSelectableFlags_SpanAllColumns))
          p.model.selection().set({item});
        ImGui::TableNextColumn();
        ImGui::Text("%.2e", e.max_gap);
        ImGui::TableNextColumn();
        ImGui::Text("%.3g", e.max_normal_angle_deg);
        ImGui::TableNextColumn();
        ImGui::Text("%.3g", e.max_mean_curvature_jump);
        if (warn) ImGui::PopStyleColor();
      }
      ImGui::EndTable();
    }
  }
  // Where the network's tangent planes could not hold every end tangent: the surface is still
  // G1 there, but the curves' tangents were changed by this much.
  if (!report.vertices.empty()) {
    ImGui::TextUnformatted("End tangents projected into the vertex plane:");
    for (const VertexReport& v : report.vertices) {
      const SelectionItem item = SelectionItem::of_point(PointRef::vertex(v.vertex));
      char label[64];
      std::snprintf(label, sizeof label, "  vertex %d: %.3g deg##pv%zu", v.vertex,
                    v.tangent_plane_deviation_deg, index);
      if (ImGui::Selectable(label, p.model.selection().contains(item)))
        p.model.selection().set({item});
    }
  }
}

}  // namespace

namespace {

// The joints of the free curves: which ends meet, the class and the figures (the same as
// `patchlab analyze` reports); a row selects the two curves.
void draw_curve_joints(const SidePanel& p) {
  const CurveMarks& marks = p.model.curve_marks();
  if (marks.joints().empty()) return;
  const std::vector<SceneCurve>& curves = p.model.doc().scene().curves;
  ImGui::Separator();
  ImGui::TextUnformatted("Curve joints");
  const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV |
                                ImGuiTableFlags_ScrollY | ImGuiTableFlags_SizingStretchProp;
  const float rows = std::min<float>(float(marks.joints().size()), 8.0f);
  const float h = ImGui::GetTextLineHeightWithSpacing() * (rows + 1.6f);
  if (!ImGui::BeginTable("curve_joints", 5, flags, ImVec2(0, h))) return;
  ImGui::TableSetupScrollFreeze(0, 1);
  // The ends' names need the room; the figures are short.
  ImGui::TableSetupColumn("joint", ImGuiTableColumnFlags_WidthStretch, 3.0f);
  ImGui::TableSetupColumn("G", ImGuiTableColumnFlags_WidthStretch, 0.45f);
  ImGui::TableSetupColumn("G0 gap", ImGuiTableColumnFlags_WidthStretch, 1.0f);
  ImGui::TableSetupColumn("G1 deg", ImGuiTableColumnFlags_WidthStretch, 1.0f);
  ImGui::TableSetupColumn("k jump", ImGuiTableColumnFlags_WidthStretch, 1.0f);
  ImGui::TableHeadersRow();
  for (std::size_t i = 0; i < marks.joints().size(); ++i) {
    const JointReport& j = marks.joints()[i];
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    const std::string label = joint_ends(j, curves) + "##joint" + std::to_string(i);
    const SelectionItem a = SelectionItem::curve(j.curves[0]),
                        b = SelectionItem::curve(j.curves[1]);
    if (ImGui::Selectable(label.c_str(),
                          p.model.selection().contains(a) && p.model.selection().contains(b),
                          ImGuiSelectableFlags_SpanAllColumns))
      p.model.selection().set({a, b});
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(joint_class(j, marks.size()).c_str());
    ImGui::TableNextColumn();
    ImGui::Text("%.2g", j.gap);
    ImGui::TableNextColumn();
    ImGui::Text("%.3g", j.tangent_angle_deg);
    ImGui::TableNextColumn();
    ImGui::Text("%.3g", j.curvature_jump);
  }
  ImGui::EndTable();
}

}  // namespace

void draw_continuity_section(const SidePanel& p) {
  double& threshold = p.model.prefs().continuity_threshold_deg;
  ImGui::InputDouble("Warn above", &threshold, 0, 0, "%.3g deg");
  threshold = std::clamp(threshold, kMinContinuityThresholdDeg, kMaxContinuityThresholdDeg);
  panel_tooltip(p,
                "An edge is a warning when the normals of its two faces differ by more\n"
                "than this anywhere along it (kept in the preferences)");
  const auto& fillings = p.model.continuity().fillings();
  for (std::size_t i = 0; i < fillings.size(); ++i) draw_filling(p, fillings[i], i, threshold);
  if (fillings.empty()) ImGui::TextDisabled("Waiting for the surfaces.");
  draw_curve_joints(p);
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
  ImGui::TextWrapped(
      "Yellow: edges over the threshold; the worst is drawn yellow in its view. "
      "A row selects its edge or vertex.");
  ImGui::PopStyleColor();
}

}  // namespace pl
