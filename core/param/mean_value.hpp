// Mean value coordinates (Floater 2003; Hormann & Floater 2006 for arbitrary simple polygons)
// with exact first and second derivatives, and the GB local parameters from them
// (parameterization.hpp).
//
// Why these for concave GB domains: Wachspress coordinates have poles over concave polygons;
// the SMI 2018 concave GB paper uses harmonic coordinates, which have no closed form (the
// authors solve a discrete Laplace problem on a bitmap), hence no exact derivatives. Mean value
// coordinates are closed-form, C-infinity inside any simple polygon, linear along the sides and
// Lagrange at the vertices; they may turn negative behind reflex vertices, which the GB ribbon
// patch checks for (see gb_ribbon_patch.hpp).
#pragma once

#include "core/math/lanes.hpp"
#include "core/param/parameterization.hpp"

namespace pl {

// lambda_i (out[i], one per polygon vertex) at x for a simple polygon (either orientation) of at
// most MeanValueParameters::kMaxSides vertices. x must not be a vertex; on a side (and near
// it) the weights are rescaled by that side's signed area so the usual 1/0 at the boundary never
// occurs and the derivatives there are the one-sided limits from the interior. O(n).
void mean_value_coordinates(std::span<const Vec2> polygon, Vec2 x, std::span<Jet> out);

class MeanValueParameters final : public Parameterization {
 public:
  static constexpr int kMaxSides = 64;

  // A simple polygon of 3..kMaxSides vertices; throws std::invalid_argument for another count.
  explicit MeanValueParameters(std::vector<Vec2> vertices);

  // h_i by sums_off_side (O(n) for all sides); s_i as the plain quotient, which is 0/0 on the
  // sides away from side i: patches that need it there take lambda instead.
  void evaluate(Vec2 x, std::span<Jet> lambda, std::span<Jet> s, std::span<Jet> h,
                SideMask sides = kAllSides) const override;
  // lambda and h (arrays of sides() entries, h of every side) for kLanes (or kWideLanes) points
  // (u[b], v[b]) at once, none of them a vertex, each lane bit for bit what evaluate() gives;
  // the WideLane form only where wide_lanes() holds.
  void evaluate_lanes(const Lane& u, const Lane& v, JetLanes* lambda, JetLanes* h) const;
  void evaluate_lanes(const WideLane& u, const WideLane& v, WideJetLanes* lambda,
                      WideJetLanes* h) const;

 private:
  template <class T>
  void sample_lanes(const T& u, const T& v, JetOf<T>* lambda, JetOf<T>* h) const;
};

}  // namespace pl
