// Plain arrays of one tessellated surface: what the renderer uploads and the exporters write.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/eval/patch_evaluator.hpp"

namespace pl {

struct SurfaceMesh {
  std::string name;
  std::vector<Vec3> positions;
  std::vector<Vec3> normals;  // unit, exact (from derivatives), outward
  std::vector<Vec2> params;   // the domain point of each vertex (messages name it)
  std::vector<double> gaussian, mean, kmin, kmax;
  std::vector<std::array<uint32_t, 3>> triangles;  // oriented like the normals
  uint64_t revision = 0;
};

SurfaceMesh make_surface_mesh(const PatchEvaluator& evaluator, std::string name);

}  // namespace pl
