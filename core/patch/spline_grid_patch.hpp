// The base of the B-spline and NURBS patches: the grid of knots and points (spline_grid.hpp), what
// a point of the grid is (on its border or not) and the curves of its sides, which do not depend
// on weights; written once for both.
#pragma once

#include <utility>
#include <vector>

#include "core/patch/spline_grid.hpp"
#include "core/patch/unit_square_patch.hpp"

namespace pl {

// Side curves of a spline grid of (homogeneous, when weighted) points; shared with NURBS.
std::vector<BezierCurve> spline_boundary_curves(const SplineGrid& g,
                                                const std::vector<Vec3>& points);

template <class Derived>
class SplineGridPatch : public UnitSquarePatch<Derived> {
 public:
  ControlPointKind kind(std::size_t k) const final {
    const std::size_t i = k / grid_.nv(), j = k % grid_.nv();
    return (i == 0 || j == 0 || i + 1 == grid_.nu() || j + 1 == grid_.nv())
               ? ControlPointKind::Boundary
               : ControlPointKind::Inner;
  }
  // Exact when a side is one polynomial span (its Bézier form); a multi-span side is returned
  // as one Bézier curve on its control polygon, which has the same end points but is not the
  // side (the interface has no piecewise or rational curve; boundary_point gives the side).
  std::vector<BezierCurve> boundary_curves() const final {
    return spline_boundary_curves(grid_, this->points_);
  }

  const SplineGrid& grid() const { return grid_; }

 protected:
  SplineGridPatch(std::vector<Vec3> points, SplineGrid grid)
      : UnitSquarePatch<Derived>(std::move(points)), grid_(std::move(grid)) {}

  SplineGrid grid_;
};

}  // namespace pl
