// The domain [0,1]^2 of tensor-product and quadrilateral Gregory patches.
// Sides, counter-clockwise: 0: v=0 (u 0->1), 1: u=1 (v 0->1), 2: v=1 (u 1->0), 3: u=0 (v 1->0).
#pragma once

#include "core/domain/domain.hpp"

namespace pl {

class UnitSquareDomain final : public Domain {
 public:
  int side_count() const override { return 4; }
  Vec2 side_point(int side, double t) const override;
  Vec2 interior_point() const override { return {0.5, 0.5}; }
  std::string key() const override { return "square"; }
  Tessellation tessellate(int density) const override;
};

}  // namespace pl
