// The scale range of the STEP and IGES export (docs/limits.md), checked by the CLI before the
// fits start. OpenCASCADE works to a fixed precision of 1e-7 units and the fits' default
// tolerance is min(1e-3, 1e-5 x size): below a size of 1e-3 the sewing no longer tells edges
// apart, above 1e4 the fits must reach better than 1e-7 of the size and run for minutes (at
// 1e12 and up they fail with a deviation of the scene's size). Every other output is exact at
// any scale the reader accepts.
#pragma once

#include <string>

#include "core/scene/scene.hpp"

namespace pl {

inline constexpr double kMinCadSize = 1e-3, kMaxCadSize = 1e4;

// The diagonal of the box around the scene's points: network vertices and handles, the points
// of explicit patches (not their derivative vectors) and of free curves. 0 for an empty scene.
double scene_point_size(const Scene& scene);

// Throws DataError(source, "", ...) naming the range and the scene's size, in short numbers,
// when the size is outside [kMinCadSize, kMaxCadSize].
void check_cad_scale(const Scene& scene, const std::string& source);

}  // namespace pl
