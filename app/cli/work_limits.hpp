// The work a command is about to do, bounded before any of it is done: the samples a scene
// takes at a density (core/io/input_limits.hpp: kMaxSamples).
#pragma once

#include <cstddef>
#include <string>

#include "core/scene/scene.hpp"

namespace pl {

// About how many samples evaluating the scene at this density takes (within a factor of two:
// the tessellation of a face's domain is made only during the evaluation).
std::size_t estimated_samples(const Scene& scene, int density);

// The largest density from 1 to `density` whose estimate is within kMaxSamples; 0 if none.
int largest_density_within(const Scene& scene, int density);

// Throws DataError(source, ...) naming the density to use instead when the scene at this density
// would take more than kMaxSamples samples.
void check_work_limits(const Scene& scene, int density, const std::string& source);

}  // namespace pl
