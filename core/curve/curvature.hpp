// Curvature of a space curve from its exact derivatives: |C' x C''| / |C'|^3.
#pragma once

#include "core/curve/bezier_curve.hpp"

namespace pl {

// 0 where the first derivative vanishes (curvature undefined; callers test speed() first).
inline double curve_curvature(const CurvePoint& c) {
  const double s = glm::length(c.d1);
  return s == 0 ? 0.0 : glm::length(glm::cross(c.d1, c.d2)) / (s * s * s);
}

}  // namespace pl
