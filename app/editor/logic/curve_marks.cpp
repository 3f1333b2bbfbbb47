#include "app/editor/logic/curve_marks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "app/editor/logic/curve_edits.hpp"

namespace pl {

namespace {

KnotTick tick_at(const SceneCurve& curve, double t, int multiplicity, bool end) {
  const CurvePoint p = evaluate(curve, t);
  return {t, multiplicity, end, p.p, p.d1};
}

}  // namespace

std::vector<KnotTick> knot_ticks(const SceneCurve& curve) {
  const double lo = curve.t_min(), hi = curve.t_max();
  std::vector<KnotTick> ticks;
  if (curve.type != CurveType::BSpline && curve.type != CurveType::Nurbs) {
    ticks.push_back(tick_at(curve, lo, 1, true));
    ticks.push_back(tick_at(curve, hi, 1, true));
    return ticks;
  }
  // Knots are non-decreasing (validated): runs of equal values are the distinct knots.
  const std::vector<double>& k = curve.knots;
  for (std::size_t i = 0; i < k.size();) {
    std::size_t j = i;
    while (j < k.size() && k[j] == k[i]) ++j;
    if (k[i] >= lo && k[i] <= hi) {
      const bool end = k[i] == lo || k[i] == hi;
      ticks.push_back(tick_at(curve, k[i], end ? 1 : int(j - i), end));
    }
    i = j;
  }
  return ticks;
}

double tick_length_px(const KnotTick& tick, double base_px) {
  if (tick.end) return 2.4 * base_px;  // across the end point's symbol, standing out of it
  return base_px * (1.0 + 0.6 * (tick.multiplicity - 1));
}

std::optional<ScreenTick> tick_on_screen(const WindowProjector& project, const KnotTick& tick,
                                         double length_px) {
  const auto c = project(tick.point);
  if (!c) return std::nullopt;
  // The tangent's direction on screen from a short step along it (a relative step: the
  // projection is smooth, so its direction is that of the projected derivative).
  Vec2 along(1.0, 0.0);
  const double speed = glm::length(tick.tangent);
  if (speed > 0) {
    const double step = 1e-4 * std::max(1.0, glm::length(tick.point));
    const auto a = project(tick.point - step / speed * tick.tangent);
    const auto b = project(tick.point + step / speed * tick.tangent);
    if (a && b && glm::length(*b - *a) > 1e-9) along = glm::normalize(*b - *a);
  }
  ScreenTick s;
  s.centre = *c;
  s.across = Vec2(-along.y, along.x);
  s.a = *c - 0.5 * length_px * s.across;
  s.b = *c + 0.5 * length_px * s.across;
  return s;
}

std::string joint_class(const JointReport& joint, double size) {
  static const char* const kClasses[] = {"G0", "G1", "G2"};
  return kClasses[joint_continuity(joint, size)];
}

std::string joint_label(const JointReport& joint, double size) {
  char buf[128];
  std::snprintf(buf, sizeof buf, "%s  gap %.2g  angle %.3g\xC2\xB0  jump %.3g",
                joint_class(joint, size).c_str(), joint.gap, joint.tangent_angle_deg,
                joint.curvature_jump);
  return buf;
}

std::string joint_ends(const JointReport& joint, const std::vector<SceneCurve>& curves) {
  std::string s;
  for (int k = 0; k < 2; ++k) {
    const int c = joint.curves[k];
    if (k) s += " - ";
    s += c >= 0 && c < int(curves.size()) ? curve_name(curves[c], c) : "?";
    s += joint.at_start[k] ? " start" : " end";
  }
  return s;
}

bool CurveMarks::follow(const std::vector<SceneCurve>& curves) {
  last_recomputed_ = last_ticks_evaluated_ = 0;
  bool changed = false;
  if (seen_.size() != curves.size()) {  // curves added or removed: all of them again
    seen_.assign(curves.size(), SceneCurve{});
    ticks_.assign(curves.size(), {});
    changed = true;
  }
  for (std::size_t c = 0; c < curves.size(); ++c) {
    const SceneCurve& curve = curves[c];
    SceneCurve& seen = seen_[c];
    if (!seen.points.empty() && same_but_points(seen, curve)) {
      // Only points moved: the ticks on their supports move, the others stay (a drag of one
      // point of a long spline costs its p + 2 knots, not the curve's).
      const auto range = moved_range(seen, curve);
      if (!range) continue;
      const auto [lo, hi] = *range;
      seen.points = curve.points;
      for (KnotTick& t : ticks_[c])
        if (t.t >= lo && t.t <= hi) {
          const CurvePoint p = evaluate(curve, t.t);
          t.point = p.p, t.tangent = p.d1;
          ++last_ticks_evaluated_;
        }
      ++last_recomputed_;
      changed = true;
      continue;
    }
    seen = curve;
    ticks_[c] = knot_ticks(curve);
    last_ticks_evaluated_ += ticks_[c].size();
    ++last_recomputed_;
    changed = true;
  }
  if (changed) {
    joints_ = curve_joints(curves);
    size_ = curves_size(curves);
  }
  return changed;
}

}  // namespace pl
