#include "app/editor/theme.hpp"

#include <imgui.h>

#include "render/font.hpp"

namespace pl {

namespace {

ImVec4 v4(const ThemeColour& c, float a = 1.0f) {
  return ImVec4(c[0], c[1], c[2], a);
}

}  // namespace

void load_ui_font(float scale, float framebuffer_scale) {
  ImGuiIO& io = ImGui::GetIO();
  io.Fonts->Clear();
  const auto ttf = embedded_font_data();
  ImFontConfig config;
  config.FontDataOwnedByAtlas = false;  // the bytes are the binary's own
  config.OversampleH = 2;               // sub-pixel placement along a line
  config.OversampleV = 1;
  const float fb = framebuffer_scale > 0 ? framebuffer_scale : 1.0f;
  io.Fonts->AddFontFromMemoryTTF(const_cast<unsigned char*>(ttf.data()), int(ttf.size()),
                                 kUiFontPixels * scale * fb, &config,
                                 io.Fonts->GetGlyphRangesDefault());
  io.FontGlobalScale = 1.0f / fb;
}

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
  s.FramePadding = ImVec2(kUiFramePadding[0], kUiFramePadding[1]);
  s.ItemSpacing = ImVec2(kUiItemSpacing[0], kUiItemSpacing[1]);
  s.IndentSpacing = 14;
  s.ScrollbarSize = 12;
  ImVec4* c = s.Colors;
  const ImVec4 accent(kAccent[0], kAccent[1], kAccent[2], 1.0f);
  const ImVec4 accent_dim(kAccent[0] * 0.75f, kAccent[1] * 0.75f, kAccent[2] * 0.75f, 1.0f);
  c[ImGuiCol_Text] = v4(kThemeText);
  c[ImGuiCol_TextDisabled] = v4(kThemeHintText);
  c[ImGuiCol_WindowBg] = v4(kThemeWindow);
  c[ImGuiCol_ChildBg] = ImVec4(0.13f, 0.135f, 0.15f, 1.00f);
  c[ImGuiCol_PopupBg] = v4(kThemePopup);
  c[ImGuiCol_Border] = ImVec4(0.26f, 0.27f, 0.30f, 1.00f);
  c[ImGuiCol_FrameBg] = v4(kThemeFrame);
  c[ImGuiCol_FrameBgHovered] = ImVec4(0.28f, 0.285f, 0.31f, 1.00f);
  c[ImGuiCol_FrameBgActive] = ImVec4(0.32f, 0.325f, 0.35f, 1.00f);
  c[ImGuiCol_TitleBg] = c[ImGuiCol_WindowBg];
  c[ImGuiCol_TitleBgActive] = ImVec4(0.19f, 0.195f, 0.21f, 1.00f);
  c[ImGuiCol_MenuBarBg] = v4(kThemeMenuBar);
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
