// The ribbons a transfinite patch blends: per side i a boundary curve P_i(s) and a cross-boundary
// derivative D_i(s) pointing into the face, both on s in [0, 1], giving the linear ribbon
// R_i(s, d) = P_i(s) + d D_i(s); and the corner data the schemes derive from them. Side i runs
// from corner i-1 to corner i, and corner i (between sides i and i+1) is P_i(1).
//
// Everything here is linear in the curves' control points (for fixed NURBS weights), which is
// what the patch's basis functions rely on.
#pragma once

#include <vector>

#include "core/curve/spline_curve.hpp"
#include "core/math/jet.hpp"
#include "core/patch/surface_jet.hpp"

namespace pl::transfinite {

// A curve on [0, 1]: a B-spline or NURBS curve whose own range [t_min, t_max] is mapped
// affinely onto [0, 1] (derivatives scaled accordingly).
class UnitCurve {
 public:
  UnitCurve() = default;
  explicit UnitCurve(SplineCurve spline);
  CurvePoint at(double s) const;
  // The same by the B-spline basis (Cox-de Boor) whatever the curve: the rounding of the research
  // library's evaluation, which its forward-difference twists magnify 1e4 times.
  CurvePoint at_by_basis(double s) const;
  const SplineCurve& spline() const { return spline_; }
  // For changing control points only (the knots and weights stay).
  SplineCurve& spline() { return spline_; }

 private:
  SplineCurve spline_;
  // A polynomial curve of one span on [0, 1] (every Bézier side, every network face): evaluated
  // by de Casteljau instead of the general B-spline basis, several times faster.
  bool bezier_ = false;
};

struct RibbonCurves {
  UnitCurve curve;  // P_i, along the side in loop order
  UnitCurve cross;  // D_i, the derivative across the side, into the face
};

// How the corner twists are taken from the cross derivatives. Exact: the derivatives D_i'(1) and
// D_{i+1}'(0). ForwardDifference: the estimate of the authors' research library (transfinite),
// (D_i(1 - h) - D_i(1)) / h and (D_{i+1}(h) - D_{i+1}(0)) / h with h = 1e-4; it moves a surface
// by up to about 1e-4 of its size and is there only to reproduce that library's numbers (the
// reference tests use it).
enum class TwistEstimate { Exact, ForwardDifference };

// The data of corner i (between sides i and i+1), the Gregory-type corner patch of the schemes:
// Q_i(a, b) = C + a' T1 + b' T2 + a' b' (a' twist2 + b' twist1) / (a' + b'),
// a' = gamma(a), b' = gamma(b) clamped to [0, 1], a measured along side i from the corner and
// b along side i+1.
struct CornerData {
  Vec3 point{0}, t1{0}, t2{0}, twist1{0}, twist2{0};
};

// gamma(d) = d / (2 d + 1): the distance reparameterization of the ribbons (transfinite's
// default), which keeps a ribbon's influence bounded far from its side.
Jet gamma(const Jet& d);
// The cubic Hermite blend H(t) = (1 - t)^3 + 3 (1 - t)^2 t (H(0) = 1, H(1) = 0).
Jet hermite_blend(const Jet& t);

class RibbonSet {
 public:
  RibbonSet(std::vector<RibbonCurves> sides, TwistEstimate twists);

  int size() const { return static_cast<int>(sides_.size()); }
  const RibbonCurves& side(int i) const { return sides_[wrap(i)]; }
  const CornerData& corner(int i) const { return corners_[wrap(i)]; }
  TwistEstimate twists() const { return twists_; }
  int wrap(int i) const {
    const int n = size();
    return ((i % n) + n) % n;
  }

  // The side interpolant I_i(s, d) = R_i(clamp(s, 0, 1), max(gamma(d), 0)).
  SurfaceJet side_interpolant(int i, const Jet& s, const Jet& d) const;
  // Q_i(a, b) as above; the rational twist term is dropped where a' + b' < 1e-8 (it vanishes
  // there to second order).
  SurfaceJet corner_correction(int i, const Jet& a, const Jet& b) const;
  // The corner interpolant K_i = I_i(s_i, s_{i+1}) + I_{i+1}(s_{i+1}, 1 - s_i)
  // - Q_i(1 - s_i, s_{i+1}) of the corner-based and midpoint schemes.
  SurfaceJet corner_interpolant(int i, const std::vector<Jet>& s) const;

 private:
  std::vector<RibbonCurves> sides_;
  std::vector<CornerData> corners_;
  TwistEstimate twists_;
};

}  // namespace pl::transfinite
