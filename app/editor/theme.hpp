// The editor's ImGui look: a calm dark-grey tool theme with one accent colour, so the coloured
// surface analysis stays the brightest thing on screen, and the embedded TrueType face (DejaVu
// Sans, render/font.hpp) at the UI scale, so text is crisp at any monitor scale. The colours
// the text sits on are constants here, so a test can check the contrast of the text and of the
// hint text (WCAG's 4.5:1 for body text) without a window.
#pragma once

#include <array>

namespace pl {

// sRGB, 0..1, opaque.
using ThemeColour = std::array<float, 3>;
inline constexpr ThemeColour kThemeText{0.90f, 0.91f, 0.93f};
// Hints, help descriptions, disabled items: quieter than text, still readable.
inline constexpr ThemeColour kThemeHintText{0.66f, 0.68f, 0.72f};
inline constexpr ThemeColour kThemeWindow{0.155f, 0.160f, 0.175f};
inline constexpr ThemeColour kThemeFrame{0.22f, 0.225f, 0.245f};  // input fields
inline constexpr ThemeColour kThemeMenuBar{0.12f, 0.125f, 0.135f};
inline constexpr ThemeColour kThemePopup{0.17f, 0.175f, 0.19f};

// The UI font's size in pixels at UI scale 1.
inline constexpr float kUiFontPixels = 15.0f;
// The space around a frame's text and between items, at UI scale 1: with the font they make the
// window's metrics (a menu bar is kUiFontPixels + 2 kUiFramePadding[1] high).
inline constexpr float kUiFramePadding[2] = {6.0f, 4.0f};
inline constexpr float kUiItemSpacing[2] = {8.0f, 6.0f};

// Colours and spacing (unscaled).
void apply_theme();
// Rebuilds the font atlas with the embedded face at `scale` (1: kUiFontPixels); framebuffer
// pixels per window pixel (HiDPI) are rasterised too, so text stays sharp there. Call between
// frames, then recreate the backend's font texture.
void load_ui_font(float scale, float framebuffer_scale);

// The accent colour (selection, active widgets) as RGBA 0..1.
constexpr float kAccent[4] = {0.96f, 0.62f, 0.16f, 1.0f};

}  // namespace pl
