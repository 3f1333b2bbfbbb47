#include "app/editor/side_panel.hpp"

#include <imgui.h>

#include <algorithm>

#include "app/editor/logic/compare_layout.hpp"
#include "app/editor/logic/editor_layout.hpp"
#include "core/analysis/compared_schemes.hpp"
#include "core/scene/network_edit.hpp"

namespace pl {

namespace {

// The Selection section keeps the tallest height it has had (up to kSelectionMostRows rows), so
// the sections below move down at most when a taller selection than ever before appears, and
// never jump back up when it shrinks or goes: what the designer aims at stays put. (A fixed
// reserve for the tallest selection would leave the Display section off screen at start.)
constexpr float kSelectionMostRows = 30;

void keep_section_height(float used, float ui_scale) {
  static float tallest = 0, scale = 0;
  if (scale != ui_scale) tallest = 0, scale = ui_scale;  // sizes in pixels follow the scale
  tallest =
      std::max(tallest, std::min(used, kSelectionMostRows * ImGui::GetFrameHeightWithSpacing()));
  ImGui::Dummy(ImVec2(0, tallest - used));  // always one item: the same spacing in every case
}

}  // namespace

bool draw_side_panel(const SidePanel& p, double top, double bottom) {
  const ImGuiIO& io = ImGui::GetIO();
  const float w = float(EditorLayout::kSidePanelWidth * p.ui_scale);
  ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x - w, float(top)));
  ImGui::SetNextWindowSize(ImVec2(w, io.DisplaySize.y - float(top + bottom)));
  ImGui::Begin("##side", nullptr,
               ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoMove |
                   ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings);
  // Widgets take what is left after a label column of fixed width, so labels never clip.
  ImGui::PushItemWidth(-110 * p.ui_scale);
  bool rebuild = false;
  draw_tools_section(p);
  if (ImGui::CollapsingHeader("Selection", ImGuiTreeNodeFlags_DefaultOpen)) {
    // As one group, so that its height is what it drew whatever its last row ends with.
    ImGui::BeginGroup();
    draw_selection_section(p);
    ImGui::EndGroup();
    keep_section_height(ImGui::GetItemRectSize().y, float(p.ui_scale));
  }
  const bool display = ImGui::CollapsingHeader("Display", ImGuiTreeNodeFlags_DefaultOpen);
  if (p.item_probe) {
    const ImVec2 lo = ImGui::GetItemRectMin(), hi = ImGui::GetItemRectMax();
    p.item_probe("Display header", lo.x, lo.y, hi.x, hi.y);
  }
  if (display) {
    rebuild = draw_display_section(p);
    // The comparison's panes are a choice of display: which schemes fill the network side by
    // side.
    if (p.model.doc().scene().network) rebuild |= draw_comparison_section(p);
  }
  if (ImGui::CollapsingHeader("Work plane")) draw_work_plane_section(p);
  if (ImGui::CollapsingHeader("Continuity", ImGuiTreeNodeFlags_DefaultOpen))
    draw_continuity_section(p);
  ImGui::PopItemWidth();
  ImGui::End();
  return rebuild;
}

void panel_tooltip(const SidePanel& p, const std::string& text) {
  if (!ImGui::IsItemHovered()) return;
  const float left =
      ImGui::GetIO().DisplaySize.x - float(EditorLayout::kSidePanelWidth * p.ui_scale);
  ImGui::SetNextWindowPos(ImVec2(left - 8 * p.ui_scale, ImGui::GetItemRectMin().y),
                          ImGuiCond_Always, ImVec2(1.0f, 0.0f));
  ImGui::BeginTooltip();
  // Wrapped, so a long help line stays within the view beside the panel.
  ImGui::PushTextWrapPos(ImGui::GetFontSize() * 28.0f);
  ImGui::TextUnformatted(text.c_str());
  ImGui::PopTextWrapPos();
  if (p.item_probe) {
    const ImVec2 at = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
    p.item_probe("tooltip", at.x, at.y, at.x + size.x, at.y + size.y);
  }
  ImGui::EndTooltip();
}

void draw_tools_section(const SidePanel& p) {
  // One button per tool, from the Tools menu's actions (their keys and enabled state).
  bool first = true;
  for (const ActionRegistry::Entry& e : p.model.actions().entries("Tools")) {
    if (!e.action) continue;
    const Action& a = *e.action;
    if (a.id == "tool.finish") continue;  // a command of the tools, not a tool
    // Buttons flow on to the next line when the panel is too narrow for them.
    const ImGuiStyle& style = ImGui::GetStyle();
    const float w = ImGui::CalcTextSize(a.label.c_str()).x + 2 * style.FramePadding.x;
    if (!first && ImGui::GetItemRectMax().x + style.ItemSpacing.x + w <
                      ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x)
      ImGui::SameLine();
    first = false;
    const bool on = a.checked && a.checked();
    if (on) ImGui::PushStyleColor(ImGuiCol_Button, ImGui::GetStyleColorVec4(ImGuiCol_ButtonActive));
    if (ImGui::Button(a.label.c_str())) p.model.actions().run(a.id);
    if (on) ImGui::PopStyleColor();
    if (p.item_probe) {
      const ImVec2 lo = ImGui::GetItemRectMin(), hi = ImGui::GetItemRectMax();
      p.item_probe(a.label, lo.x, lo.y, hi.x, hi.y);
    }
    panel_tooltip(p, a.help + (a.keys.empty() ? "" : "  (" + to_string(a.keys[0]) + ")"));
  }
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
  ImGui::TextWrapped("%s", p.model.tools().active().hint().c_str());
  ImGui::PopStyleColor();
  if (p.item_probe) {
    const ImVec2 lo = ImGui::GetItemRectMin(), hi = ImGui::GetItemRectMax();
    p.item_probe("Tool hint", lo.x, lo.y, hi.x, hi.y);
  }
  draw_tool_options(p);
}

void draw_work_plane_section(const SidePanel& p) {
  WorkPlane& w = p.model.work_plane();
  ImGui::Checkbox("Show grid", &w.shown);
  int kind = static_cast<int>(w.kind);
  static const char* kinds[] = {"View", "XY", "XZ", "YZ"};
  if (ImGui::Combo("Plane", &kind, kinds, 4)) w.kind = static_cast<WorkPlaneKind>(kind);
  double origin[3] = {w.origin.x, w.origin.y, w.origin.z};
  if (ImGui::InputScalarN("Through", ImGuiDataType_Double, origin, 3, nullptr, nullptr, "%.4g"))
    w.origin = Vec3(origin[0], origin[1], origin[2]);
  if (p.model.actions().find("plane.at_selection")) {
    const Action& a = *p.model.actions().find("plane.at_selection");
    ImGui::BeginDisabled(!p.model.actions().is_enabled(a));
    if (ImGui::Button("Through the selection")) p.model.actions().run(a.id);
    ImGui::EndDisabled();
  }
  ImGui::TextDisabled("New points are placed on this plane.");
}

bool draw_comparison_section(const SidePanel& p) {
  ImGui::Separator();
  ImGui::TextUnformatted("Compare schemes");
  const Action* compare = p.model.actions().find("view.compare");
  bool on = p.model.views().compare();
  if (compare && ImGui::Checkbox("Side by side  (C)", &on)) p.model.actions().run(compare->id);
  CompareSetup setup =
      compare_setup_from(p.model.prefs().compare_schemes, p.model.prefs().compare_base);
  const CompareSetup before = setup;
  // Panes and their schemes; a change re-evaluates the comparison (rebuild).
  int count = int(setup.schemes.size());
  const std::string count_label = std::to_string(count) + " panes";
  if (ImGui::BeginCombo("Panes", count_label.c_str())) {
    for (int c : kComparePaneCounts)
      if (ImGui::Selectable((std::to_string(c) + " panes").c_str(), c == count))
        setup = with_pane_count(setup, c);
    ImGui::EndCombo();
  }
  const std::vector<FaceScheme> all = comparable_schemes();
  for (int i = 0; i < int(setup.schemes.size()); ++i) {
    const std::string label = "Pane " + std::to_string(i + 1);
    if (ImGui::BeginCombo(label.c_str(), scheme_title(setup.schemes[i]).c_str())) {
      for (FaceScheme s : all)
        if (ImGui::Selectable(scheme_title(s).c_str(), s == setup.schemes[i]))
          setup = with_pane_scheme(setup, i, s);
      ImGui::EndCombo();
    }
  }
  if (ImGui::BeginCombo("Base", scheme_title(setup.base).c_str())) {
    for (FaceScheme s : setup.schemes)
      if (ImGui::Selectable(scheme_title(s).c_str(), s == setup.base)) setup.base = s;
    ImGui::EndCombo();
  }
  panel_tooltip(p, "The distance colouring and the table's distances are to this scheme");
  bool rebuild = false;
  if (!(setup == before)) {
    p.model.prefs().compare_schemes = schemes_keywords(setup);
    p.model.prefs().compare_base = scheme_keyword(setup.base);
    // A new base alone needs no evaluation: the panes stay, their distances follow.
    if (setup.schemes == before.schemes)
      p.model.views().set_base(setup.base);
    else
      rebuild = p.model.views().compare();
  }
  if (!p.model.views().compare()) return rebuild;
  ImGui::Checkbox("Colour by distance to base  (D)", &p.model.views().difference);
  if (p.model.views().difference)
    ImGui::TextWrapped(
        "Signed distance of each sample to the nearest point of the base pane's "
        "tessellation; max |d| = %.3g",
        p.model.views().difference_max());
  return rebuild;
}

}  // namespace pl
