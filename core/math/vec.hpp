// Vector types of the core: double precision everywhere (GLM's dvec*).
#pragma once

#include <cmath>
#include <glm/glm.hpp>

namespace pl {

using Vec2 = glm::dvec2;
using Vec3 = glm::dvec3;

// The z component of the 3D cross product of two plane vectors: twice the signed area of the
// triangle (0, a, b), positive when b lies to the left of a.
inline double cross(Vec2 a, Vec2 b) {
  return a.x * b.y - a.y * b.x;
}

// Every coordinate finite (no NaN, no infinity): the one test of a point or vector the checks of
// evaluations, curves, meshes and edits share.
inline bool finite(const Vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

}  // namespace pl
