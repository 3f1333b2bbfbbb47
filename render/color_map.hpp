// The diverging curvature colour map (blue - white - red, white at zero) and the value range it
// spans. GL-free: the GPU samples a texture built from color_map(), and the legend and tests
// call the same function, so the three can never disagree.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "core/mesh/surface_mesh.hpp"

namespace pl {

using Rgb = std::array<float, 3>;  // sRGB, 0..1

// t in [0, 1]; 0.5 is the neutral colour for curvature zero. Values outside are clamped.
Rgb color_map(double t);

enum class CurvatureKind { Gaussian, Mean, Kmin, Kmax };
const char* curvature_name(CurvatureKind kind);  // "gaussian", "mean", "kmin", "kmax"
const std::vector<double>& curvature_values(const SurfaceMesh& mesh, CurvatureKind kind);

// [lo, hi] with lo < 0 < hi, mapped piecewise-linearly so that zero stays at the neutral colour:
// lo -> 0, 0 -> 0.5, hi -> 1.
struct ColorRange {
  double lo = -1, hi = 1;
  double normalized(double value) const;
};

// The symmetric range [-R, R] where R is the `percentile` (0..100) of |value| over every mesh,
// so a few extreme samples (near singular corners) do not wash out the map. Non-finite values
// are ignored; a flat (all-zero) field gives [-1, 1].
ColorRange automatic_range(std::span<const SurfaceMesh* const> meshes, CurvatureKind kind,
                           double percentile = 98.0);

// `entries` RGB float samples of the map at t = i / (entries - 1), for the GPU texture. Float
// texels keep the only rounding at the final 8-bit output.
std::vector<float> color_map_table(int entries);

}  // namespace pl
