// A tessellation of a parameter domain: where a patch is sampled, independent of the patch.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/math/vec.hpp"

namespace pl {

struct Tessellation {
  int density = 0;
  std::vector<Vec2> points;                        // domain points (the samples)
  std::vector<std::array<uint32_t, 3>> triangles;  // counter-clockwise in the domain
  // For each domain side: the indices of its density + 1 samples, at side parameter k / density,
  // from the side's start vertex (k = 0) to its end vertex (k = density).
  std::vector<std::vector<uint32_t>> sides;
};

}  // namespace pl
