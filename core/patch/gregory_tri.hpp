// Triangular Gregory patch over the unit triangle (L. Longhi, "Interpolating patches between
// cubic boundaries", UC Berkeley report UCB/CSD 85/249, 1985): a
// quartic Bézier triangle whose three interior points are each split into two twins, one per
// adjacent side, blended rationally in barycentric coordinates. The boundaries are quartic
// (network edges are cubic and enter degree-elevated): a quartic triangle has the three
// interior points needed for two Chiyokura–Kimura points per side, a cubic one only one.
//
// Domain (core/domain/unit_triangle.hpp): A = (0,0), B = (1,0), C = (0,1); barycentric
// coordinates a = 1-u-v, b = u, c = v. Sides: 0: A->B, 1: B->C, 2: C->A.
// b_{ijk} is the quartic control point with exponents (i, j, k) of (a, b, c).
//
// Point order (18 points): 12 boundary points counter-clockwise from A, four per side starting
// at the side's start corner, then per side its two twins in side direction.
//
//                  C 8                    side 0 (A->B): 0 1 2 3   = b400 b310 b220 b130
//                   / \                   side 1 (B->C): 4 5 6 7   = b040 b031 b022 b013
//                  9   7                  side 2 (C->A): 8 9 10 11 = b004 b103 b202 b301
//                 /     \                 (point 4 is B = b040, point 8 is C = b004)
//               10 16 15 6                twins:
//               /         \                 b211 (near A): 12 (side 0) | 17 (side 2)
//             11 17    14  5                b121 (near B): 13 (side 0) | 14 (side 1)
//             /  12   13    \               b112 (near C): 15 (side 1) | 16 (side 2)
//          A 0 -- 1 -- 2 -- 3 -- 4 B
//
// Twin weights (the twin of side X, where that side's coordinate x vanishes, is weighted by
// (1 - x) times the coordinate of the corner's other side):
//   b211 = ((1-c) b T12 + (1-b) c T17) / ((1-c) b + (1-b) c)
//   b121 = ((1-c) a T13 + (1-a) c T14) / ((1-c) a + (1-a) c)
//   b112 = ((1-a) b T15 + (1-b) a T16) / ((1-a) b + (1-b) a)
// Each denominator vanishes only at its corner, where the weights are 1/2 with zero
// derivatives (the blended quartic functions vanish there to third order; see twin_weight.hpp).
#pragma once

#include "core/domain/unit_triangle.hpp"
#include "core/patch/patch.hpp"

namespace pl {

class GregoryTriPatch final : public PatchType<GregoryTriPatch> {
 public:
  static constexpr const char* kType = "gregory-tri";  // the scene-format type name
  static constexpr std::size_t kPointCount = 18;
  // Point j in 0..4 of side s (j = 4 is the next side's start corner).
  static constexpr std::size_t boundary_index(int side, int j) {
    return static_cast<std::size_t>((4 * side + j) % 12);
  }
  // Twin k in {0, 1} of side s (k = 0 nearer the side's start).
  static constexpr std::size_t twin_index(int side, int k) {
    return static_cast<std::size_t>(12 + 2 * side + k);
  }

  // Throws std::invalid_argument unless there are 18 points.
  explicit GregoryTriPatch(std::vector<Vec3> points);

  const Domain& domain() const override { return domain_; }
  ControlPointKind kind(std::size_t k) const override;
  void basis(Vec2 x, std::span<Jet> out) const override;
  std::vector<BezierCurve> boundary_curves() const override;

 private:
  UnitTriangleDomain domain_;
};

}  // namespace pl
