// Wachspress coordinates of a convex polygon and the GB local parameters from them, as the
// Generalized Bézier papers (Várady, Salvi, Karikó 2016) and the transfinite library define
// them (parameterization.hpp). The forms are chosen so that nothing is 0/0 inside the closed
// polygon:
//  * Wachspress weights in product form w_i = C_i * prod_{m not adjacent to v_i} L_m(x), with
//    L_m the (linear) signed area of x and side m: polynomials, never singular;
//  * s_i = C_i L_{i-1} / (C_{i-1} L_{i+1} + C_i L_{i-1}): the common factor of lambda_{i-1} and
//    lambda_i cancelled, so s_i stays defined (and accurate) on the far sides where both lambdas
//    vanish. Only for triangles it is 0/0, at the vertex opposite side i;
//  * h_i as the sum of the other weights (sums_off_side), over their total.
// One template computes one sample (Jet) or a block of samples (one per SIMD lane), so the
// batched paths of the GB patch get the scalar path's numbers bit for bit.
#pragma once

#include "core/math/lanes.hpp"
#include "core/param/parameterization.hpp"

namespace pl {

class WachspressParameters final : public Parameterization {
 public:
  static constexpr int kMaxSides = 16;

  // vertices: counter-clockwise, strictly convex (checked by ConvexPolygonDomain), 3..kMaxSides;
  // throws std::invalid_argument for another count.
  explicit WachspressParameters(std::vector<Vec2> vertices);

  void evaluate(Vec2 x, std::span<Jet> lambda, std::span<Jet> s, std::span<Jet> h,
                SideMask sides = kAllSides) const override;
  // The same for kLanes (or kWideLanes) points (u[b], v[b]) at once, s and h only (arrays of
  // sides() entries); the WideLane form only where wide_lanes() holds.
  void evaluate_lanes(const Lane& u, const Lane& v, JetLanes* s, JetLanes* h,
                      SideMask sides = kAllSides) const;
  void evaluate_lanes(const WideLane& u, const WideLane& v, WideJetLanes* s, WideJetLanes* h,
                      SideMask sides = kAllSides) const;

 private:
  // The one body of both: T = double (one sample) or a lane type. Any output may be null.
  template <class T>
  void sample(const T& u, const T& v, JetOf<T>* lambda, JetOf<T>* s, JetOf<T>* h,
              SideMask sides) const;

  std::vector<double> corner_;  // C_i = cross(v_i - v_{i-1}, v_{i+1} - v_i)
};

}  // namespace pl
