// A free curve as a chain of cubic Bézier spans, the form of a network edge: what turning a drawn
// or imported curve into network edges needs.
//
// Each span is the cubic Hermite interpolant of the curve on a parameter interval [a, b]: its end
// points and end derivatives (one-sided at a break of the curve), so consecutive spans join with
// the curve's own continuity (C1 where the curve is C1). A curve that is one cubic (a cubic or
// lower Bézier, a Hermite or an interpolating cubic, a B-spline of degree <= 3 with one span) is
// one span, exact up to rounding. Any other curve is bisected in its parameter (at the knot
// nearest the middle where the interval holds knots, so breaks become span ends) until every
// span is within the tolerance: the distance between span and curve at equal parameters, checked
// at kFitChecks points of every knot span of the curve inside it, which bounds the distance from
// each checked curve point to the chain.
#pragma once

#include <array>
#include <vector>

#include "core/curve/scene_curve.hpp"

namespace pl {

struct CubicChain {
  std::vector<std::array<Vec3, 4>> spans;  // consecutive spans share their end points
  std::vector<double> breaks;              // the curve parameters of the span ends (spans + 1)
  double deviation = 0;                    // the largest checked distance to the curve
};

constexpr int kFitChecks = 32;

// The chain within `tolerance` (> 0, in the curve's units) of at most `max_spans` spans, or
// std::invalid_argument naming why not (a tolerance that is not positive, a curve that needs more
// spans, a curve broken in two at a knot: its name in the message is the caller's).
CubicChain cubic_chain(const SceneCurve& curve, double tolerance, int max_spans = 256);

}  // namespace pl
