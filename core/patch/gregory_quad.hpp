// Quadrilateral Gregory patch over [0,1]^2 (Chiyokura–Kimura / Gregory 1974): a bicubic Bézier
// patch whose four interior points are each split into two "twins", one per adjacent side, and
// blended rationally so that each side's cross-boundary derivative depends only on its own
// twins. That is what lets every side take its own Chiyokura–Kimura tangent field without the
// twist compatibility problem.
//
// Point order (20 points): 12 boundary points counter-clockwise from (0,0), three per side
// starting at the side's start corner, then per side its two twins in side direction.
// P_ij (i along u, j along v) is the bicubic grid position.
//
//   v ^  9 --- 8 ---- 7 ---- 6         boundary:  side s owns 3s, 3s+1, 3s+2; its end corner is
//     |  |  (18) 17  16 (15) |           the next side's start (side 3 ends at point 0)
//     | 10  P12        P22   5         twins (grid position: side twin | other side twin):
//     |  |                   |           P11: 12 (side 0) | 19 (side 3)
//     | 11  P11        P21   4           P21: 13 (side 0) | 14 (side 1)
//     |  |  (19) 12  13 (14) |           P22: 15 (side 1) | 16 (side 2)
//     |  0 --- 1 ---- 2 ---- 3           P12: 17 (side 2) | 18 (side 3)
//     +-------------------------> u
//
// Twin weights: the twin of side X has the weight "distance to the corner's other side", so it
// alone survives on side X (Chiyokura–Kimura, SIGGRAPH 1983):
//   P11 = (u T12 + v T19) / (u + v)              P21 = ((1-u) T13 + v T14) / ((1-u) + v)
//   P22 = ((1-v) T15 + (1-u) T16) / (2 - u - v)  P12 = (u T17 + (1-v) T18) / (u + (1-v))
// At a corner the weights are 0/0. Value and first derivatives of the blended basis function
// have a limit there (the Bernstein factor vanishes to second order); the twist does not (it
// depends on the direction of approach), so at the corner both weights are 1/2 with zero
// derivatives: the twist is the mean of the twins and S_uu, S_vv are the boundary curves'.
#pragma once

#include "core/domain/unit_square.hpp"
#include "core/patch/patch.hpp"

namespace pl {

class GregoryQuadPatch final : public PatchType<GregoryQuadPatch> {
 public:
  static constexpr const char* kType = "gregory-quad";  // the scene-format type name
  static constexpr std::size_t kPointCount = 20;
  // Point j in 0..3 of side s (j = 3 is the next side's start corner).
  static constexpr std::size_t boundary_index(int side, int j) {
    return static_cast<std::size_t>((3 * side + j) % 12);
  }
  // Twin k in {0, 1} of side s (k = 0 nearer the side's start).
  static constexpr std::size_t twin_index(int side, int k) {
    return static_cast<std::size_t>(12 + 2 * side + k);
  }

  // Throws std::invalid_argument unless there are 20 points.
  explicit GregoryQuadPatch(std::vector<Vec3> points);

  const Domain& domain() const override { return domain_; }
  ControlPointKind kind(std::size_t k) const override;
  void basis(Vec2 x, std::span<Jet> out) const override;
  std::vector<BezierCurve> boundary_curves() const override;

 private:
  UnitSquareDomain domain_;
};

}  // namespace pl
