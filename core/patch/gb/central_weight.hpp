// The blend of a GB face's central point (GBInteriorPatch): a bump over the domain polygon that
// vanishes with its first derivatives on every side and peaks well inside the polygon, convex or
// concave.
//
// Built from the sides' own geometry, not from the ribbon parameters: on a concave domain the
// mean value h_i of a far side measures nothing like the distance to that side (it exceeds 1 behind
// a reflex corner), so a product of the h_i peaks beside the reflex corner instead of in the middle
// of the face. Here each side i (from a = vertex i-1 to b = vertex i, unit direction e) has
//   g_i = f^2 + R_a^2 + R_b^2,   f = e x (x - a)            (distance to the side's line),
//   R_a = (|x - a| - (x - a).e) / 2,   R_b = (|x - b| + (x - b).e) / 2,
// a smooth stand-in for the squared distance d^2 to the segment: R_a^2 and R_b^2 vanish to fourth
// order in f over the segment and grow like d^2 past its ends, so g_i is zero exactly on side i,
// zero with its gradient there (g_i = f^2 + O(f^4)), between d^2 and 2.25 d^2 elsewhere, and
// C-infinity everywhere but at the two vertices. The weight is the
// product of the sides' saturated distances
//   w = prod_i g_i / (g_i + c),   c = area / (4 pi)   (half the radius of the disc with the
//                                                     domain's area, squared),
// so a side counts only within about sqrt(c) of it, unlike the mean value h_i: w vanishes like g_i
// (with its first derivatives) on every side and like g_a g_b (to fourth order, with its second
// derivatives) at the vertices, and peaks near the point farthest from the boundary (the centre
// of a regular polygon; in the corner square of an L, below the notch of a notched square). O(n)
// per sample: one square root per vertex, a reciprocal per side.
#pragma once

#include <span>
#include <vector>

#include "core/domain/concave_polygon.hpp"
#include "core/math/jet.hpp"
#include "core/math/lanes.hpp"
#include "core/math/vec.hpp"

namespace pl {

class CentralWeight {
 public:
  // The weight over the domain, normalised so that its largest value over the domain is 1: the
  // best of a sample of the domain, refined by Newton steps on the gradient.
  explicit CentralWeight(const ConcavePolygonDomain& domain);

  // w(x) / max w, with exact first and second derivatives; 0 (with its derivatives) at the
  // domain's vertices. x in the closed domain.
  Jet operator()(Vec2 x) const { return unnormalised(x) * scale_; }
  // w(x) itself.
  Jet unnormalised(Vec2 x) const;
  // operator() at every point, a block of points at a time in SIMD lanes: the same numbers.
  void evaluate_many(std::span<const Vec2> xs, std::span<Jet> out) const;
  // Where the weight peaks (1 there), and 1 / w there; scale() is 0 if no finite positive maximum
  // was found (a degenerate domain), and then operator() is 0 everywhere.
  Vec2 peak() const { return peak_; }
  double scale() const { return scale_; }

 private:
  struct Side {
    Vec2 a, e;      // the start vertex and the unit direction
    double length;  // |b - a|
  };
  // w at one sample (T = double) or one per lane, off the vertices.
  template <class T>
  JetOf<T> weight_at(const T& u, const T& v) const;
  void weight_lanes(const Lane& u, const Lane& v, Jet* out) const;
  void weight_lanes(const WideLane& u, const WideLane& v, Jet* out) const;
  template <class V>
  void weight_blocks(std::span<const Vec2> xs, std::span<Jet> out) const;

  std::vector<Vec2> vertices_;
  std::vector<Side> sides_;
  double reach_ = 1;  // c above
  Vec2 peak_{0};
  double scale_ = 0;
};

}  // namespace pl
