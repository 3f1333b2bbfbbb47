// The triangle domain of triangular patches: points (u, v) with u, v >= 0, u + v <= 1; the
// third barycentric coordinate is w = 1 - u - v. Vertices: A = (0,0) (w = 1), B = (1,0) (u = 1),
// C = (0,1) (v = 1). Sides, counter-clockwise: 0: A->B (v = 0), 1: B->C (w = 0), 2: C->A (u = 0).
#pragma once

#include "core/domain/domain.hpp"

namespace pl {

class UnitTriangleDomain final : public Domain {
 public:
  int side_count() const override { return 3; }
  Vec2 side_point(int side, double t) const override;
  Vec2 interior_point() const override { return {1.0 / 3, 1.0 / 3}; }
  std::string key() const override { return "triangle"; }
  Tessellation tessellate(int density) const override;
};

}  // namespace pl
