#include "app/editor/theme.hpp"

#include <imgui.h>

namespace pl {

void apply_theme() {
  ImGuiStyle& s = ImGui::GetStyle();
  ImGui::StyleColorsDark(&s);
  s.WindowRounding = 0;
  s.ChildRounding = 3;
  s.FrameRounding = 3;
  s.PopupRounding = 3;
  s.GrabRounding = 3;
  s.TabRounding = 3;
  s.ScrollbarRounding = 3;
  s.WindowBorderSize = 0;
  s.FrameBorderSize = 0;
  s.WindowPadding = ImVec2(10, 8);
  s.FramePadding = ImVec2(6, 4);
  s.ItemSpacing = ImVec2(8, 6);
  s.IndentSpacing = 14;
  s.ScrollbarSize = 12;
  ImVec4* c = s.Colors;
  const ImVec4 accent(kAccent[0], kAccent[1], kAccent[2], 1.0f);
  const ImVec4 accent_dim(kAccent[0] * 0.75f, kAccent[1] * 0.75f, kAccent[2] * 0.75f, 1.0f);
  c[ImGuiCol_Text] = ImVec4(0.90f, 0.91f, 0.93f, 1.00f);
  c[ImGuiCol_TextDisabled] = ImVec4(0.52f, 0.54f, 0.58f, 1.00f);
  c[ImGuiCol_WindowBg] = ImVec4(0.155f, 0.160f, 0.175f, 1.00f);
  c[ImGuiCol_ChildBg] = ImVec4(0.13f, 0.135f, 0.15f, 1.00f);
  c[ImGuiCol_PopupBg] = ImVec4(0.17f, 0.175f, 0.19f, 0.98f);
  c[ImGuiCol_Border] = ImVec4(0.26f, 0.27f, 0.30f, 1.00f);
  c[ImGuiCol_FrameBg] = ImVec4(0.22f, 0.225f, 0.245f, 1.00f);
  c[ImGuiCol_FrameBgHovered] = ImVec4(0.28f, 0.285f, 0.31f, 1.00f);
  c[ImGuiCol_FrameBgActive] = ImVec4(0.32f, 0.325f, 0.35f, 1.00f);
  c[ImGuiCol_TitleBg] = c[ImGuiCol_WindowBg];
  c[ImGuiCol_TitleBgActive] = ImVec4(0.19f, 0.195f, 0.21f, 1.00f);
  c[ImGuiCol_MenuBarBg] = ImVec4(0.12f, 0.125f, 0.135f, 1.00f);
  c[ImGuiCol_Header] = ImVec4(0.23f, 0.235f, 0.255f, 1.00f);
  c[ImGuiCol_HeaderHovered] = ImVec4(0.29f, 0.295f, 0.32f, 1.00f);
  c[ImGuiCol_HeaderActive] = ImVec4(0.33f, 0.335f, 0.36f, 1.00f);
  c[ImGuiCol_Button] = ImVec4(0.25f, 0.255f, 0.275f, 1.00f);
  c[ImGuiCol_ButtonHovered] = ImVec4(0.31f, 0.315f, 0.34f, 1.00f);
  c[ImGuiCol_ButtonActive] = accent_dim;
  c[ImGuiCol_CheckMark] = accent;
  c[ImGuiCol_SliderGrab] = accent_dim;
  c[ImGuiCol_SliderGrabActive] = accent;
  c[ImGuiCol_Tab] = c[ImGuiCol_Header];
  c[ImGuiCol_TabHovered] = c[ImGuiCol_HeaderHovered];
  c[ImGuiCol_TabActive] = ImVec4(0.30f, 0.305f, 0.33f, 1.00f);
  c[ImGuiCol_Separator] = c[ImGuiCol_Border];
  c[ImGuiCol_TableHeaderBg] = ImVec4(0.20f, 0.205f, 0.22f, 1.00f);
  c[ImGuiCol_TableRowBgAlt] = ImVec4(1, 1, 1, 0.03f);
  c[ImGuiCol_TextSelectedBg] = ImVec4(kAccent[0], kAccent[1], kAccent[2], 0.35f);
  c[ImGuiCol_NavHighlight] = accent;
  c[ImGuiCol_ModalWindowDimBg] = ImVec4(0, 0, 0, 0.45f);
}

}  // namespace pl
