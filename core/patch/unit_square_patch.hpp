// The base of the patch types over the unit square (Bézier, B-spline, NURBS, Coons network): the
// domain, held and returned once for all of them.
#pragma once

#include <utility>
#include <vector>

#include "core/domain/unit_square.hpp"
#include "core/patch/patch.hpp"

namespace pl {

template <class Derived>
class UnitSquarePatch : public PatchType<Derived> {
 public:
  const Domain& domain() const final { return domain_; }

 protected:
  explicit UnitSquarePatch(std::vector<Vec3> points) : PatchType<Derived>(std::move(points)) {}

  UnitSquareDomain domain_;
};

}  // namespace pl
