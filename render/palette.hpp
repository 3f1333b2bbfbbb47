// Every colour the overlays use, in one place, so the shaders, the burned-in keys and the editor's
// own drawing agree and a test can check that they stay apart from each other and from the
// curvature colour map (sRGB, 0..1). GL-free.
#pragma once

#include <array>

#include "render/color_map.hpp"

namespace pl::palette {

// Point kinds, in the core's ControlPointKind order (Boundary, Inner, Twin, Central, Curve,
// FreeInterior).
// Editable points are filled with these, derived ones drawn as rings of them.
inline constexpr std::array<Rgb, 6> kPointKinds{{
    {0.93f, 0.47f, 0.08f},  // boundary: orange square
    {0.16f, 0.45f, 0.90f},  // inner: blue disc
    {0.78f, 0.22f, 0.78f},  // twin: magenta diamond
    {0.13f, 0.62f, 0.30f},  // central: green triangle
    {0.74f, 0.10f, 0.22f},  // curve (a free curve's point): crimson hexagon
    {0.00f, 0.80f, 0.90f},  // free interior (of a network GB face): cyan pentagon
}};
inline constexpr Rgb kPointOutline{0.08f, 0.08f, 0.09f};
inline constexpr Rgb kDerivedPointFill{0.98f, 0.98f, 0.97f};

// Control-net lines: between editable points dark, touching a derived point lighter.
inline constexpr Rgb kNetLine{0.20f, 0.22f, 0.26f};
inline constexpr Rgb kDerivedNetLine{0.42f, 0.44f, 0.50f};

// Derivative data drawn as arrows from their base point.
inline constexpr Rgb kTangentArrow{0.45f, 0.18f, 0.62f};  // violet
inline constexpr Rgb kTwistArrow{0.55f, 0.38f, 0.05f};    // ochre

inline constexpr Rgb kNetworkCurve{0.05f, 0.30f, 0.62f};
inline constexpr Rgb kBorder{0.12f, 0.13f, 0.16f};
inline constexpr Rgb kCombTeeth{0.00f, 0.55f, 0.50f};
inline constexpr Rgb kCombEnvelope{0.00f, 0.45f, 0.40f};

// What the editor points at (a picked edge, a warning): saturated yellow, a hue no colour map
// (blue - white - red), no point kind and no other overlay uses, so it stays visible on every
// display mode.
inline constexpr Rgb kHighlight{1.00f, 0.93f, 0.00f};

// Ink for burned-in text and the frames of keys and legends; their panels are opaque.
inline constexpr Rgb kInk{0.13f, 0.14f, 0.17f};
inline constexpr Rgb kPanel{1.0f, 1.0f, 1.0f};
inline constexpr Rgb kPanelFrame{0.62f, 0.64f, 0.68f};

}  // namespace pl::palette
