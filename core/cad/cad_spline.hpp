// The B-spline curves and surfaces a CAD file receives: clamped knot vectors over [0, 1],
// any degree up to OpenCASCADE's 25, optional positive weights (NURBS). Plain data with the
// operations the export needs (evaluation with first derivatives, exact knot insertion, exact
// degree elevation of Bézier pieces, reversal); no OpenCASCADE here.
#pragma once

#include <span>
#include <vector>

#include "core/curve/bezier_curve.hpp"
#include "core/math/vec.hpp"

namespace pl {

inline constexpr int kMaxCadDegree = 25;  // Geom_BSplineSurface::MaxDegree()

// The non-zero basis functions of degree p at t and their first derivatives (the NURBS book's
// algorithm with one derivative): N_{span-p+r} at value[r], derivative[r].
struct CadBasis {
  int span = 0;
  std::vector<double> value, derivative;
};
CadBasis cad_basis(int p, std::span<const double> knots, std::size_t n, double t);

// The distinct knot values of a clamped knot vector and their multiplicities.
struct KnotRun {
  double value;
  int multiplicity;
};
std::vector<KnotRun> knot_runs(std::span<const double> knots);

struct CadCurve {
  int degree = 1;
  std::vector<double> knots;  // size points.size() + degree + 1, clamped, from 0 to 1
  std::vector<Vec3> points;

  static CadCurve from_bezier(const BezierCurve& b);
  CurvePoint evaluate(double t) const;  // d2 is left zero
  CadCurve reversed() const;            // C(1 - t)
  // The same curve of degree p >= degree (each Bézier span elevated; interior knots keep their
  // continuity because every multiplicity rises by p - degree).
  CadCurve elevated_to(int p) const;
  // The same curve with every knot of `target` (a clamped vector of the same degree that
  // contains this curve's knots as a sub-multiset) inserted; throws std::invalid_argument if
  // `target` does not contain them.
  CadCurve refined_to(const std::vector<double>& target) const;
};

struct CadSurface {
  int degree_u = 1, degree_v = 1;
  std::vector<double> knots_u, knots_v;  // clamped, from 0 to 1
  std::size_t nu = 0, nv = 0;
  std::vector<Vec3> points;     // points[i * nv + j], i along u
  std::vector<double> weights;  // empty (polynomial) or one positive weight per point

  const Vec3& at(std::size_t i, std::size_t j) const { return points[i * nv + j]; }
  bool rational() const { return !weights.empty(); }
  // Position and first derivatives (rational quotient rule where weighted).
  struct Jet1 {
    Vec3 p, su, sv;
  };
  Jet1 evaluate(double u, double v) const;
  // The iso-curve u = 0, u = 1 (running in v) or v = 0, v = 1 (running in u) of a polynomial
  // surface: its boundary row of control points with the matching knot vector.
  CadCurve boundary(int side) const;  // side 0: v=0, 1: u=1, 2: v=1, 3: u=0 (all increasing)
};

// Throws std::invalid_argument unless knots and counts are consistent, the knot vectors are
// clamped over [0, 1], degrees are within 1..25 and weights are positive and finite.
void validate_cad_surface(const CadSurface& s);

// A clamped knot vector of degree p whose distinct values are the union of those of a and b,
// each with the larger multiplicity (both clamped over [0, 1], same degree).
std::vector<double> merge_knots(int p, const std::vector<double>& a, const std::vector<double>& b);

// Clamped knots of degree p over [0, 1] with `spans` equal spans (simple interior knots).
std::vector<double> uniform_knots(int p, int spans);

}  // namespace pl
