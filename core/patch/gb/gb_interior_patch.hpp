// The GB patch of a curve-network face with interior control: the face's default filling plus
// the displacements of the free points of a degree-d GB net, each through its own blend,
//   S(x) = F(x) + sum_p (C_p - D_p) phi_p(x),
// F the default filling (an independent-ribbon GB patch, gb_ribbon_patch.hpp), C_p a free point
// of the degree-d net and D_p its default position.
//
// The degree-d net is a .gbp net (n sides, degree d, l = ceil(d/2) layers, gbp-format.md): its
// rings 0 and 1 carry the face's G1 data and are not free; every point of ring >= 2 and the
// central point C_0 are free. phi_p is the blend the point has in the degree-d independent-ribbon
// patch over F's domain (SMI 2018): layer k of ribbon i blends with
//   b^i_{j,k} / sum of all blends,   b^i_{j,k} = mu^i_j B^d_j(s_i) B^{2l-1}_k(h_i),
// and a corner-block point named by two ribbons has the sum of both blends. Sides that need more
// layers than l (behind a reflex corner, gb_ribbon_patch.hpp) carry their rows elevated in h
// (ribbon_with_layer), so there phi_p is the combination of the elevated rows' blends. C_0 blends
// with phi_0, the soft minimum of the domain sides' smoothed squared distances normalised so that
// its largest value over the domain is 1 (central_weight.hpp): zero with its first derivatives on
// every side, and peaking well inside the face, near the point farthest from its boundary (the
// centre of the regular n-gon, the domain of every convex face), also behind reflex corners.
//
// Every phi_p vanishes with its first derivatives on the whole boundary (rows 0 and 1 carry no
// displacement), so the boundary curves and the cross-boundary derivatives are F's at every
// degree and for every offset: G1 with the neighbouring faces is F's. With C_p = D_p for all p
// the surface is F, bit for bit (the displacement part is not evaluated at all).
//
// Control points, so that S = sum_k C_k phi_k holds and the basis sums to 1:
//   [0, net_size())                 the degree-d net in .gbp order (free points phi_p, the G1
//                                   rings 0 and 1 have phi = 0: shown, not blended);
//   [net_size(), + F.size())        F's control points with F's basis;
//   then one per free point         its default D_p, with basis -phi_p (free_points() order).
// A drag of a free point is therefore one influence column, delta * phi_p.
#pragma once

#include <optional>
#include <utility>
#include <vector>

#include "core/patch/gb/central_weight.hpp"
#include "core/patch/gb/gb_ribbon_patch.hpp"

namespace pl {

class GBInteriorPatch final : public PatchType<GBInteriorPatch> {
 public:
  // A network-face form, not a scene type of its own: scenes store the face, not this patch.
  static constexpr const char* kType = "gb-ribbons-interior";

  // `defaults` and `net`: the degree-d .gbp net, GBPatch::point_count(n, d) points each (n the
  // filling's side count), `net` = defaults + offsets at the free points; rings 0 and 1 of `net`
  // should equal `defaults` (they are drawn, never blended). Throws std::invalid_argument for
  // wrong sizes, d < 3, a degree-d ribbon patch the filling's domain cannot carry, or a moved
  // C_0 on a domain where phi_0 cannot be normalised (it vanishes everywhere).
  GBInteriorPatch(GBRibbonPatch filling, int degree, const std::vector<Vec3>& defaults,
                  const std::vector<Vec3>& net);

  const Domain& domain() const override { return filling_.domain(); }
  ControlPointKind kind(std::size_t k) const override;
  void set_control_point(std::size_t k, const Vec3& p) override;
  void basis(Vec2 x, std::span<Jet> out) const override;
  SurfaceJet evaluate(Vec2 x) const override;
  void evaluate_many(std::span<const Vec2> xs, std::span<SurfaceJet> out) const override;
  void influence(std::size_t k, std::span<const Vec2> xs, std::span<Jet> out) const override;
  std::vector<BezierCurve> boundary_curves() const override { return filling_.boundary_curves(); }

  int sides() const { return filling_.sides(); }
  int degree() const { return d_; }
  std::size_t net_size() const { return net_size_; }
  const GBRibbonPatch& filling() const { return filling_; }
  // The net indices of the free points: ring >= 2 in .gbp order, and 0 (C_0) first when the
  // domain carries phi_0.
  const std::vector<std::size_t>& free_points() const { return free_; }
  bool is_free(std::size_t k) const { return k < net_size_ && free_slot_[k] >= 0; }
  bool has_centre() const { return centre_; }
  // Control point index of the default of free net point k.
  std::size_t default_index(std::size_t k) const;
  // C_k - D_k for free net point k.
  Vec3 offset(std::size_t k) const { return points_[k] - points_[default_index(k)]; }
  // phi_k at x for free net point k, without the other basis functions.
  Jet free_blend(std::size_t k, Vec2 x) const;

 private:
  struct Term {
    std::size_t q;  // storage index in blends_
    double c;
  };
  Jet centre_weight(Vec2 x) const;
  // The displacement of blend storage point q: sum over its terms of c (C_p - D_p).
  void update_blend_point(std::size_t q);
  void add_displacement(Vec2 x, SurfaceJet& s) const;
  std::size_t free_slot(std::size_t k) const { return static_cast<std::size_t>(free_slot_[k]); }

  GBRibbonPatch filling_;
  int d_;
  std::size_t net_size_;
  // The degree-d independent-ribbon patch over F's domain whose control points are the
  // displacements of its rows (rows 0 and 1 zero); absent when d has no free ring (d < 5).
  std::optional<GBRibbonPatch> blends_;
  std::vector<std::size_t> free_;
  std::vector<int> free_slot_;            // [net index] -> position in free_, or -1
  std::vector<std::vector<Term>> terms_;  // [free slot] -> blend storage points
  std::vector<std::vector<std::pair<std::size_t, double>>> users_;  // [q] -> (free slot, c)
  std::size_t displaced_points_ = 0;  // blend points with a non-zero displacement
  bool centre_ = false;
  CentralWeight centre_weight_;  // phi_0
};

}  // namespace pl
