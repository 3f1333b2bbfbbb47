#include "app/editor/editor_windows.hpp"

#include <imgui.h>

#include <algorithm>

namespace pl {

void draw_status_bar(const StatusLine& status, const StatusFigures& f, float s) {
  const ImGuiIO& io = ImGui::GetIO();
  const float h = ImGui::GetFrameHeight() + 6 * s;
  ImGui::SetNextWindowPos(ImVec2(0, io.DisplaySize.y - h));
  ImGui::SetNextWindowSize(ImVec2(io.DisplaySize.x, h));
  ImGui::PushStyleColor(ImGuiCol_WindowBg, ImGui::GetStyleColorVec4(ImGuiCol_MenuBarBg));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(8 * s, 3 * s));
  ImGui::Begin("##status", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                   ImGuiWindowFlags_NoBringToFrontOnFocus);
  ImGui::Text("%s  |  eval %.1f ms (%s)  |  frame %.1f ms  |  settle %.0f ms  |  %zu selected",
              f.tool.c_str(), status.eval_ms, f.coarse ? "coarse" : "fine",
              status.median_frame_ms(), status.settle_ms, f.selected);
  if (!f.under.empty()) {
    ImGui::SameLine();
    ImGui::TextDisabled("  |  %s", f.under.c_str());
  }
  if (!f.drawing.empty()) {
    ImGui::SameLine();
    ImGui::TextDisabled("  |  %s", f.drawing.c_str());
  }
  if (!f.plane.empty()) {
    ImGui::SameLine();
    ImGui::TextDisabled("  |  %s", f.plane.c_str());
  }
  const std::string message = status.message();
  if (!message.empty()) {
    ImGui::SameLine();
    ImGui::TextColored(ImVec4(1.0f, 0.7f, 0.4f, 1), "  |  %s", message.c_str());
  }
  ImGui::End();
  ImGui::PopStyleVar();
  ImGui::PopStyleColor();
}

void draw_help_window(bool* open, const ActionRegistry& actions, float s) {
  ImGui::SetNextWindowSize(ImVec2(640 * s, 560 * s), ImGuiCond_Appearing);
  ImGui::SetNextWindowPos(ImVec2(60 * s, 80 * s), ImGuiCond_Appearing);
  if (!ImGui::Begin("Mouse and keys", open, ImGuiWindowFlags_NoSavedSettings)) {
    ImGui::End();
    return;
  }
  const std::vector<HelpRow> rows = help_rows(actions, mouse_help());
  // The keys column as wide as its widest entry; the descriptions wrap in what is left.
  float keys_width = 0;
  for (const HelpRow& r : rows)
    keys_width = std::max(keys_width, ImGui::CalcTextSize(r.keys.c_str()).x);
  if (ImGui::BeginTable("help", 2, ImGuiTableFlags_RowBg)) {
    ImGui::TableSetupColumn("keys", ImGuiTableColumnFlags_WidthFixed, keys_width);
    ImGui::TableSetupColumn("what", ImGuiTableColumnFlags_WidthStretch);
    for (const HelpRow& r : rows) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(r.keys.c_str());
      ImGui::TableNextColumn();
      ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
      ImGui::TextWrapped("%s", r.what.c_str());
      ImGui::PopStyleColor();
    }
    ImGui::EndTable();
  }
  ImGui::End();
}

void draw_probe_window(const ProbeHit& p, const std::string& name, float s) {
  // A small read-out that follows the cursor, offset so it never hides what is probed.
  const ImGuiIO& io = ImGui::GetIO();
  ImGui::SetNextWindowPos(ImVec2(io.MousePos.x + 18 * s, io.MousePos.y + 18 * s));
  ImGui::SetNextWindowBgAlpha(0.85f);
  ImGui::Begin("##probe", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                   ImGuiWindowFlags_NoInputs | ImGuiWindowFlags_NoSavedSettings |
                   ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav);
  if (!name.empty()) ImGui::TextDisabled("%s", name.c_str());
  ImGui::Text("p   %8.4f %8.4f %8.4f", p.position.x, p.position.y, p.position.z);
  ImGui::Text("n   %8.4f %8.4f %8.4f", p.normal.x, p.normal.y, p.normal.z);
  ImGui::Text("k1  %10.4g   k2 %10.4g", p.k1, p.k2);
  ImGui::Text("K   %10.4g   H  %10.4g", p.gaussian, p.mean);
  ImGui::End();
}

}  // namespace pl
