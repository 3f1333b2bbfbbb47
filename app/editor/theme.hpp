// The editor's ImGui colours and spacing: a calm dark-grey tool theme with one accent colour,
// so the coloured surface analysis stays the brightest thing on screen.
#pragma once

namespace pl {

void apply_theme();

// The accent colour (selection, active widgets) as RGBA 0..1.
constexpr float kAccent[4] = {0.96f, 0.62f, 0.16f, 1.0f};

}  // namespace pl
