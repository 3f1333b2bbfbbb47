// The figures `analyze` reports for free curves: arc length, curvature range, inflections; and
// the joints of concatenated curves (gap, tangent angle, curvature jump: G0, G1, G2).
#pragma once

#include <array>
#include <span>
#include <string>
#include <vector>

#include "core/curve/scene_curve.hpp"

namespace pl {

struct CurveReport {
  std::string name, type;
  int degree = 0, control_points = 0, spans = 0;
  double length = 0;
  std::array<double, 2> curvature{0, 0};  // min, max of kappa over the samples
  int inflections = 0;
  std::size_t nonfinite_samples = 0;
};

struct JointReport {
  std::array<int, 2> curves{-1, -1};
  // Per curve: its start (true) or end (false) is the one at the joint.
  std::array<bool, 2> at_start{false, false};
  Vec3 position{0.0};  // the first curve's end point there (where the editor labels the joint)
  double gap = 0, tangent_angle_deg = 0, curvature_jump = 0;
  std::array<double, 2> curvature{0, 0};  // |kappa| of each curve at the joint
};

// The geometric continuity a joint's figures show: 2 (G2) when the tangents agree within
// `angle_deg` and the curvature vectors within `relative` of the larger curvature (or both
// curvatures are below `relative` / size, straight there), 1 (G1) when only the tangents agree,
// else 0 (G0: the ends meet). `size`: the curves' size (the same one curve_joints measures
// gaps with).
int joint_continuity(const JointReport& j, double size, double angle_deg = 1e-6,
                     double relative = 1e-6);

// Arc length by Gauss-Legendre quadrature on every span, each piece halved until its halves
// agree with it to 1e-13 of the span's length, or to the rounding of C' (64 eps times the degree
// times the largest coordinate) where that is larger, at most 12 halvings deep; only the pieces
// that need it are halved.
double curve_length(const SceneCurve& c);

// Signed-curvature sign changes along t for a planar curve (0 for a curve that is not planar or
// is straight), from the curve's samples at curve_sample_parameters(c, per_span).
int curve_inflections(const SceneCurve& c, int per_span);

// `name` is the curve's name or curve<i>; samples: per_span per span.
CurveReport analyze_curve(const SceneCurve& c, const std::string& name, int per_span);

// The figures of a joint where one curve arrives (a, with its derivatives in the direction of
// travel) and the next leaves (b): the distance, the angle between the tangents in degrees and
// the length of the difference of the curvature vectors.
JointReport joint_figures(const CurvePoint& a, const CurvePoint& b);

// The curves' size: the diagonal of the bounding box of their (spline form's) control points.
double curves_size(std::span<const SceneCurve> curves);

// Every pair of curve ends within 1e-9 of the curves' size (the diagonal of the bounding box of
// their control points): an end and the start or end of another curve, or the two ends of one
// closed curve.
std::vector<JointReport> curve_joints(std::span<const SceneCurve> curves);

// Throws DataError(source, "curves[index]", ...) naming the first parameter where the curve's
// position, derivatives, curvature or arc length are not finite (numbers in range whose
// products overflow, e.g. a huge weight on a huge coordinate): the figures, pictures and
// exports of a curve are finite or refused.
void check_curve_finite(const SceneCurve& c, std::size_t index, int per_span,
                        const std::string& source);

// analyze_curve's report (name: curve_name(c, index)) after check_curve_finite's checks, with the
// samples and the length computed once for both.
CurveReport checked_curve_report(const SceneCurve& c, std::size_t index, int per_span,
                                 const std::string& source);

// Curvature vector kappa N = (C'' - (C''.T) T) / |C'|^2: the same whichever way the curve runs.
Vec3 curvature_vector(const CurvePoint& c);

}  // namespace pl
