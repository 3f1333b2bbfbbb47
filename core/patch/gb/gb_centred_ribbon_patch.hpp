// A GB patch with independent ribbons (gb_ribbon_patch.hpp) plus a central control point, the
// form of a curve-network GB face with interior control (core/network/gb_face.hpp).
//
// The ribbon patch has no central point (its blends are normalised). The central point C_0 enters
// as a displacement from its default position D (the default-net rule, default_net.hpp), with
// a bubble weight that vanishes to second order on every side:
//   S(x) = R(x) + phi_0(x) (C_0 - D),   phi_0 = prod_i h_i(x)^2 / prod_i h_i(c)^2,
// R the ribbon patch, h_i the mean value local parameters (zero on side i), c the average of the
// domain vertices (the centre of the regular n-gon). So the boundary curves and the first
// derivatives along every side are the ribbon patch's (G1 with the neighbours is untouched) and
// C_0 = D gives R exactly. Both C_0 and D are stored control points (the last two), with basis
// functions phi_0 and -phi_0: S = sum phi_k C_k holds and the basis sums to 1.
#pragma once

#include <vector>

#include "core/param/mean_value.hpp"
#include "core/patch/gb/gb_ribbon_patch.hpp"

namespace pl {

class GBCentredRibbonPatch final : public PatchType<GBCentredRibbonPatch> {
 public:
  // A network-face form, not a scene type of its own: scenes store the face, not this patch.
  static constexpr const char* kType = "gb-ribbons-centred";

  // Throws std::invalid_argument if phi_0 cannot be normalised (c outside the domain or on a
  // curve where some h_i vanishes).
  GBCentredRibbonPatch(GBRibbonPatch ribbons, Vec3 centre, Vec3 centre_default);

  const Domain& domain() const override { return ribbons_.domain(); }
  ControlPointKind kind(std::size_t k) const override;
  void set_control_point(std::size_t k, const Vec3& p) override;
  void basis(Vec2 x, std::span<Jet> out) const override;
  SurfaceJet evaluate(Vec2 x) const override;
  void evaluate_many(std::span<const Vec2> xs, std::span<SurfaceJet> out) const override;
  void influence(std::size_t k, std::span<const Vec2> xs, std::span<Jet> out) const override;
  std::vector<BezierCurve> boundary_curves() const override { return ribbons_.boundary_curves(); }

  const GBRibbonPatch& ribbon_patch() const { return ribbons_; }
  std::size_t centre_index() const { return ribbons_.size(); }
  std::size_t centre_default_index() const { return ribbons_.size() + 1; }
  // The bubble weight phi_0 at x.
  Jet centre_weight(Vec2 x) const;

 private:
  GBRibbonPatch ribbons_;
  MeanValueParameters params_;
  double scale_ = 1;  // 1 / prod_i h_i(c)^2
};

}  // namespace pl
