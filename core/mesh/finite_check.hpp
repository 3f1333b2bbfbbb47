// Finite by construction: nothing PatchLab writes (OBJ, PLY, OFF, STL, PNG, analyze) may hold a
// non-finite number or a zero "unit" normal. Singular samples already carry their limit from
// inside the domain (PatchEvaluator); a sample that has no limit either, or overflowed, stops the
// output with a DataError naming the patch and the domain parameter.
#pragma once

#include <span>
#include <string>

#include "core/eval/patch_evaluator.hpp"
#include "core/mesh/surface_mesh.hpp"

namespace pl {

// Throws DataError(source, "patch \"NAME\" at (u, v) = (...)", what is wrong) for the first bad
// sample: a position, normal or curvature that is not finite, or a normal that is not unit.
void check_finite(const PatchEvaluator& evaluator, const std::string& name,
                  const std::string& source);
void check_finite(std::span<const SurfaceMesh> meshes, const std::string& source);

}  // namespace pl
