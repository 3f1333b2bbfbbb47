// A similarity of space about a pivot: x -> pivot + scale * R (x - pivot) + shift, with R a
// rotation (orthonormal, determinant +1) and scale > 0. Directions (normals, tangents) turn by R
// only. It is what the editor's move, rotate and scale apply to a selection: angles are kept, so
// a tangent plane and the handles in it stay a tangent plane and handles in it.
#pragma once

#include <cmath>

#include "core/math/vec.hpp"

namespace pl {

struct Similarity {
  Vec3 pivot{0};
  glm::dmat3 rotation{1.0};
  double scale = 1;
  Vec3 shift{0};

  Vec3 point(const Vec3& x) const { return pivot + scale * (rotation * (x - pivot)) + shift; }
  Vec3 direction(const Vec3& d) const { return rotation * d; }

  static Similarity translation(const Vec3& by) { return {.shift = by}; }
  static Similarity scaling(const Vec3& pivot, double factor) {
    return {.pivot = pivot, .scale = factor};
  }
  // The rotation by `radians` about the axis through `pivot` along `axis` (right-handed;
  // Rodrigues' formula). The axis need not be a unit vector; it must not be zero.
  static Similarity rotation_about(const Vec3& pivot, const Vec3& axis, double radians) {
    const Vec3 k = glm::normalize(axis);
    const double c = std::cos(radians), s = std::sin(radians), t = 1 - c;
    // glm matrices are column-major: m[column][row].
    glm::dmat3 r;
    r[0] = Vec3(t * k.x * k.x + c, t * k.x * k.y + s * k.z, t * k.x * k.z - s * k.y);
    r[1] = Vec3(t * k.x * k.y - s * k.z, t * k.y * k.y + c, t * k.y * k.z + s * k.x);
    r[2] = Vec3(t * k.x * k.z + s * k.y, t * k.y * k.z - s * k.x, t * k.z * k.z + c);
    return {.pivot = pivot, .rotation = r};
  }
  // Whether it is one (finite entries, R orthonormal with determinant +1 to 1e-9, scale > 0).
  bool valid() const {
    if (!finite(pivot) || !finite(shift) || !std::isfinite(scale) || !(scale > 0)) return false;
    const glm::dmat3 e = glm::transpose(rotation) * rotation;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        if (!std::isfinite(e[i][j]) || std::fabs(e[i][j] - (i == j ? 1.0 : 0.0)) > 1e-9)
          return false;
    return glm::determinant(rotation) > 0;
  }
};

}  // namespace pl
