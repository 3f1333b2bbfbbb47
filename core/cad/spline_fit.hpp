// Least-squares B-spline fits (Eigen) of curves and four-sided surface pieces whose boundary
// rows are pinned to given curves, refined (more knots) until the deviation at a check grid
// four times denser than the fit's samples is within the tolerance. Position deviation is the
// distance at equal parameters, an upper bound of the distance between the two surfaces.
#pragma once

#include <array>
#include <atomic>
#include <chrono>
#include <cstddef>
#include <functional>
#include <span>

#include "core/cad/cad_spline.hpp"
#include "core/curve/bezier_curve.hpp"

namespace pl {

// A fit's work is the number of grid points it evaluates and compares (fit samples and check
// points, summed over its refinements): it bounds the time of one fit whatever the function.
// A refinement that would pass max_work is not started, the first one included (the fit then has
// no result); one that would start after the deadline neither. Either way the fit reports
// failure, saying which bound stopped it.
inline constexpr std::size_t kDefaultFitWork = std::size_t(1) << 21;
// The same summed over every fit of one export (shared by the fits running in parallel).
inline constexpr std::size_t kDefaultExportWork = std::size_t(1) << 24;

struct FitTolerance {
  double position = 1e-3;    // scene units
  double normal_deg = 0.05;  // surfaces: normal angle; curves: tangent angle
  int max_spans = 64;        // per direction; beyond it the fit reports failure
  std::size_t max_work = kDefaultFitWork;
  std::chrono::steady_clock::time_point deadline = std::chrono::steady_clock::time_point::max();
  // Optional: the work of all fits together, and its bound.
  std::atomic<std::size_t>* shared_work = nullptr;
  std::size_t max_shared_work = kDefaultExportWork;
};

// Why a fit ended.
enum class FitEnd {
  Converged,   // within the tolerance
  Spans,       // no span left to split (max_spans, or spans too short)
  Curve,       // a fitted side curve's error bends the surface past the tolerance (fit_check.hpp)
  Work,        // the next refinement would pass max_work
  SharedWork,  // the next refinement would pass max_shared_work
  Deadline,    // the deadline passed
};

// A surface point with its first derivatives in the piece's (u, v).
struct SurfacePoint {
  Vec3 p, su, sv;
};
// Evaluates the surface being fitted at many (u, v) in [0, 1]^2 at once.
using SurfaceFunction = std::function<void(std::span<const Vec2>, std::span<SurfacePoint>)>;
// Evaluates a curve (position and first derivative) at many t in [0, 1] at once.
using CurveFunction = std::function<void(std::span<const double>, std::span<CurvePoint>)>;

// Fit samples per knot span (in each direction) for degree p and `spans` spans: two where the
// spans alone give enough equations, else p. The check grid has four times as many (a surface
// fit's has twice as many while it misses; fit_surface).
int fit_samples_per_span(int p, int spans);

struct CurveFit {
  CadCurve curve;
  double position_deviation = 0;  // largest at the check points
  double tangent_deviation_deg = 0;
  int check_points = 0;
  bool converged = false;
  FitEnd end = FitEnd::Spans;
  std::size_t work = 0;  // grid points evaluated and compared
};

// Degree p, uniform knots, end points pinned to g(0) and g(1).
CurveFit fit_curve(const CurveFunction& g, int degree, const FitTolerance& tol);

struct SurfaceFit {
  CadSurface surface;
  double position_deviation = 0;  // largest at the check grid (the last one checked)
  double normal_deviation_deg = 0;
  int fit_samples = 0;       // per direction (of the final fit)
  int check_points = 0;      // per direction
  int singular_normals = 0;  // check points where the fitted function has no normal
  bool converged = false;
  FitEnd end = FitEnd::Spans;
  std::size_t work = 0;  // grid points evaluated and compared
};

// sides (each running in increasing parameter): 0: v = 0, 1: u = 1, 2: v = 1, 3: u = 0; their
// end points must agree at the corners. The degree in u is that of sides 0 and 2, in v that of
// sides 1 and 3 (the larger of each pair, at least 3); a lower-degree side is elevated exactly
// and every side's knots are kept (refinement only adds knots), so the fitted boundary rows are
// the given curves exactly.
SurfaceFit fit_surface(const SurfaceFunction& f, const std::array<CadCurve, 4>& sides,
                       const FitTolerance& tol);

}  // namespace pl
