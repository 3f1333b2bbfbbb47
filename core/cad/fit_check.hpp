// The check of a surface fit (spline_fit.hpp) against the function it fits, on a tensor grid of
// check points: its largest deviations, and the knot spans to bisect where it misses.
//
// Where a cell (a pair of knot spans) misses, it is bisected in the direction along which its
// deviation varies: a fit that cannot follow the function across a cell leaves that detail in its
// deviation, so a deviation that changes from check point to check point along u asks for knots
// in u, one that is the same along u but changes along v asks for knots in v (both when the two
// are comparable). The cell's size in space says nothing about that. At the rim of a many-sided
// GB face (on the 64-sided cap of the unit sphere the normal turns by about 60 degrees within a
// tenth of the domain's radius from the boundary, while the surface moves by 0.004) the cells
// along the boundary are shortest in space across the rim, which is where they need the knots;
// bisected by their size, they were split along the side instead, round after round: a ring
// piece of that cap ended with 45 x 24 spans and 368,553 grid points of work, where it needs
// 20 x 28 and 149,317.
#pragma once

#include <span>
#include <vector>

#include "core/cad/spline_fit.hpp"

namespace pl {

// One direction of a check grid: `per_span` equal steps in every knot span, and the end, so that
// span r holds the check points r * per_span .. (r + 1) * per_span (its end is the next one's
// first).
struct CheckAxis {
  std::span<const double> t;
  int per_span = 1;
  int spans() const { return static_cast<int>(t.size() - 1) / per_span; }
};

struct FitCheck {
  double position = 0, normal_deg = 0;  // the largest deviations
  int singular = 0;                     // check points where the function has no normal
  bool pinned_bend = false;             // a miss comes from a pinned side (see check_fit)
  std::vector<char> split_u, split_v;   // per knot span: bisect it
  bool within(const FitTolerance& tol) const {
    return position <= tol.position && normal_deg <= tol.normal_deg;
  }
};

// truth[a * v.t.size() + b] and fit[...] are the function and the fitted surface at
// (u.t[a], v.t[b]). A miss next to a pinned side whose own position error (a fitted curve's),
// taken up across the span next to it, turns the normal by more than half the tolerance is a
// pinned bend: no bisection helps it (across the side it steepens the bend and doubles the miss,
// along it the fit still has to bend to the curve), and since spans only get shorter, neither
// does going on: the side curve has to be tightened.
FitCheck check_fit(std::span<const SurfacePoint> truth, std::span<const SurfacePoint> fit,
                   const CheckAxis& u, const CheckAxis& v, const FitTolerance& tol);

}  // namespace pl
