// The documented limits of what PatchLab reads and evaluates, checked before any work (each with
// a located message). docs/limits.md explains each number.
#pragma once

#include <cstddef>

#include "core/patch/catmull_clark_limit.hpp"

namespace pl {

// A scene or .gbp file is read whole and parsed in memory (about ten times its size).
inline constexpr std::size_t kMaxInputBytes = std::size_t(256) << 20;

// Every coordinate x must satisfy |x| <= kMaxCoordinate. The evaluation squares lengths of
// differences of control points (|p - q|^2: normals, curvature, tangent lengths); with every
// coordinate within B, |p - q|^2 <= 3 (2B)^2 = 12 B^2, which stays finite for
// B = sqrt(DBL_MAX / 12) = 3.87e153. A little below that.
inline constexpr double kMaxCoordinate = 3.8e153;

// The control points of a patch (or of the network) must span at least this much: below it the
// squared span sqrt(DBL_MIN) = 1.49e-154 is no longer a normal double and lengths lose every digit.
inline constexpr double kMinSpan = 1.5e-154;

// A network face or GB patch has at most this many sides.
inline constexpr int kMaxFaceSides = 64;

// A Catmull-Clark control mesh: at most this many vertices in a face and faces around a vertex,
// and vertices in all (core/patch/catmull_clark_limit.hpp says why).
inline constexpr int kMaxCatmullClarkValence = CatmullClarkLimit::kMaxValence;
inline constexpr std::size_t kMaxCatmullClarkVertices = CatmullClarkLimit::kMaxVertices;

// Sampling: --density N samples each boundary curve at t = k/N; a command evaluates at most
// kMaxSamples samples in all (jet, geometry, tessellation and mesh take about 400 bytes a
// sample: 1.7 GB at the limit), checked from the scene before any evaluation.
inline constexpr int kMaxDensity = 4096;
inline constexpr std::size_t kMaxSamples = std::size_t(1) << 22;

}  // namespace pl
