// The one check every command runs before it reports or writes anything, so that what `analyze`
// refuses, `render` and every export (OBJ, PLY, OFF, STL, STEP, IGES) refuse with the same
// message, and before any writer starts: the work bound (docs/limits.md), then every surface
// sample finite with a unit normal (core/mesh/finite_check.hpp), then every free curve finite
// (core/analysis/curve_analysis.hpp).
#pragma once

#include <optional>
#include <string>

#include "core/analysis/curve_analysis.hpp"
#include "core/eval/scene_surfaces.hpp"

namespace pl {

// The density of commands run without --density; STEP and IGES, which take no density, are
// checked at it, so they refuse what `analyze FILE` refuses.
inline constexpr int kDefaultDensity = 32;

// The scene's surfaces evaluated at the density, each checked finite, and its free curves
// checked finite at `density` samples per span. Throws DataError(file, ...) on the first refusal.
// With `curve_reports`, the curves' analyze figures are made from the same samples (one report
// per curve, in order), so `analyze` evaluates each curve once. With a pool, the surfaces' sample
// storage comes from it and goes back to it (evaluate_scene).
SceneSurfaces evaluate_checked(const Scene& scene, int density, std::optional<FaceScheme> scheme,
                               TessellationCache& cache, const std::string& file,
                               std::vector<CurveReport>* curve_reports = nullptr,
                               const std::shared_ptr<SampleBufferPool>& pool = nullptr);

}  // namespace pl
