// Local parameters of a convex polygon domain, as the Generalized Bézier papers (Várady, Salvi,
// Karikó 2016) and the transfinite library define them: Wachspress coordinates lambda_i of the
// vertices, and for every side i (vertex i-1 -> vertex i) the side parameter
// s_i = lambda_i / (lambda_{i-1} + lambda_i) and the distance parameter h_i = 1 - lambda_{i-1} -
// lambda_i, all as Jets (exact first and second (u, v) derivatives).
//
// Kept apart from GBPatch so that other multi-sided patches (independent-ribbon GB, ...) reuse
// it. The forms are chosen so that nothing is 0/0 inside the closed polygon:
//  * Wachspress weights in product form w_i = C_i * prod_{m not adjacent to v_i} L_m(x), with
//    L_m the (linear) signed area of x and side m: polynomials, never singular;
//  * s_i = C_i L_{i-1} / (C_{i-1} L_{i+1} + C_i L_{i-1}): the common factor of lambda_{i-1} and
//    lambda_i cancelled, so s_i stays defined (and accurate) on the far sides where both lambdas
//    vanish. Only for triangles it is 0/0, at the vertex opposite side i;
//  * h_i as the sum of the other lambdas, so it keeps full relative accuracy near side i (the
//    GB corner weights divide h's by each other).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "core/math/jet.hpp"
#include "core/math/lanes.hpp"
#include "core/math/vec.hpp"

namespace pl {

class PolygonParameters {
 public:
  static constexpr int kMaxSides = 16;

  // vertices: counter-clockwise, strictly convex (checked by ConvexPolygonDomain), 3..kMaxSides.
  explicit PolygonParameters(std::vector<Vec2> vertices);

  int sides() const { return n_; }
  const Vec2& vertex(int i) const { return vertices_[wrap(i)]; }
  int wrap(int i) const { return ((i % n_) + n_) % n_; }

  // Each span has sides() entries; any of them may be empty to skip that output. s and h are
  // computed only for the sides whose bit is set in `sides` (the others are left untouched).
  void evaluate(Vec2 x, std::span<Jet> lambda, std::span<Jet> s, std::span<Jet> h,
                uint32_t sides = ~0u) const;
  // The same for kLanes points (u[b], v[b]) at once, s and h only (arrays of sides() entries);
  // the WideLane form only where wide_lanes() holds.
  void evaluate_lanes(const Lane& u, const Lane& v, JetLanes* s, JetLanes* h,
                      uint32_t sides = ~0u) const;
  void evaluate_lanes(const WideLane& u, const WideLane& v, WideJetLanes* s, WideJetLanes* h,
                      uint32_t sides = ~0u) const;

 private:
  Jet side_area(int m, Vec2 x) const;  // L_m(x), > 0 inside
  template <class V>
  void lanes(const V& u, const V& v, JetLanesOf<V>* s, JetLanesOf<V>* h, uint32_t sides) const;

  int n_;
  std::vector<Vec2> vertices_;
  std::vector<double> corner_;  // C_i = cross(v_i - v_{i-1}, v_{i+1} - v_i)
};

}  // namespace pl
