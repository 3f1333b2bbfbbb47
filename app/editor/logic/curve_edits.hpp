// What an edit of a free curve changed, for the parts of the editor that follow curves
// incrementally (combs, knot ticks): whether only point positions moved, and the parameter range
// those moves change (a B-spline or NURBS point k moves [t_k, t_{k+p+1}] only). GUI-free.
#pragma once

#include <optional>
#include <utility>

#include "core/curve/scene_curve.hpp"

namespace pl {

// Equal but for (some of) the points' positions (a drag, a nudge, typed coordinates).
bool same_but_points(const SceneCurve& a, const SceneCurve& b);

// The parameter range the moved points of `now` change, as against `before` (same_but_points);
// nullopt when no point moved. Polynomial types (one span): the whole range.
std::optional<std::pair<double, double>> moved_range(const SceneCurve& before,
                                                     const SceneCurve& now);

}  // namespace pl
