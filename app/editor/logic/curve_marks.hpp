// What the editor marks on the scene's free curves besides their lines: the knots, as short
// ticks across the curve (at every distinct knot value in the curve's range, the ends included;
// a multiple interior knot gets a longer tick and its multiplicity as a label), and the joints of
// concatenated curves (an end on another curve's start or end) with their G0/G1/G2 figures, from
// the core's joint analysis, the one `patchlab analyze` reports. Kept per curve: an edit of one
// curve recomputes that curve's ticks only, and a moved point only the ticks on its support.
// GUI-free and unit-tested.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "app/editor/logic/view_math.hpp"
#include "core/analysis/curve_analysis.hpp"

namespace pl {

struct KnotTick {
  double t = 0;
  int multiplicity = 1;  // of the knot value in the knot vector (ends: 1)
  bool end = false;      // the curve's start or end
  Vec3 point{0.0};       // on the curve
  Vec3 tangent{0.0};     // C'(t) (the right-hand piece at a knot; zero where C' vanishes)
};

// The ticks of one curve, in t order: B-spline and NURBS curves at each distinct knot value of
// [t_min, t_max]; the polynomial types (one span) at their two ends.
std::vector<KnotTick> knot_ticks(const SceneCurve& curve);

// A tick's length on screen: the ends 2.4 base (out of the end point's symbol), an interior knot
// base (1 + 0.6 (m - 1)).
double tick_length_px(const KnotTick& tick, double base_px);

// The tick as a segment on screen, `length_px` long, centred on the curve and across its
// projected tangent (across the window's x axis where the tangent points at the eye or
// vanishes). nullopt when the point is behind the eye.
struct ScreenTick {
  Vec2 centre{0.0}, a{0.0}, b{0.0};
  Vec2 across{0.0};  // unit, from centre to b (a label goes further along it)
};
std::optional<ScreenTick> tick_on_screen(const WindowProjector& project, const KnotTick& tick,
                                         double length_px);

// "G2", "G1" or "G0", as joint_continuity classifies the joint's figures.
std::string joint_class(const JointReport& joint, double size);
// "G1  gap 0  angle 0.000°  jump 0.427": the class and figures, as the view labels a joint.
std::string joint_label(const JointReport& joint, double size);
// "curve0 end - curve1 start", with the curves' names.
std::string joint_ends(const JointReport& joint, const std::vector<SceneCurve>& curves);

class CurveMarks {
 public:
  // Brings the ticks and joints up to `curves`. Returns true when anything changed.
  bool follow(const std::vector<SceneCurve>& curves);
  // Per curve.
  const std::vector<std::vector<KnotTick>>& ticks() const { return ticks_; }
  const std::vector<JointReport>& joints() const { return joints_; }
  double size() const { return size_; }  // the curves' size (curves_size)
  // Curves whose ticks the last follow() recomputed, and the ticks it evaluated (for tests).
  std::size_t last_recomputed() const { return last_recomputed_; }
  std::size_t last_ticks_evaluated() const { return last_ticks_evaluated_; }

 private:
  std::vector<SceneCurve> seen_;
  std::vector<std::vector<KnotTick>> ticks_;
  std::vector<JointReport> joints_;
  double size_ = 0;
  std::size_t last_recomputed_ = 0, last_ticks_evaluated_ = 0;
};

}  // namespace pl
