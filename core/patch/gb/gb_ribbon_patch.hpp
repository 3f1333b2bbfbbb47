// Generalized Bézier patch with independent ribbons (Salvi & Várady, "Multi-sided Bézier
// surfaces over concave polygonal domains", SMI 2018), over a convex or concave polygon.
//
// Side i (domain side i, from vertex i-1 to vertex i) carries ribbon i: degree d_i along the side,
// l_i >= 2 layers, control points C^i_{j,k} (j = 0..d_i along the side, k = 0..l_i-1 inwards;
// row k = 0 is the boundary curve). With lambda the mean value coordinates of the domain,
//   s_i = lambda_i / (lambda_i-1 + lambda_i),   h_i = 1 - lambda_i-1 - lambda_i,
//   blend  b^i_{j,k} = mu^i_{j,k} B^{d_i}_j(s_i) B^{2 l_i - 1}_k(h_i),
//   mu = h_{i-1}^2 / (h_{i-1}^2 + h_i^2) for 2j < d_i,  1 for 2j = d_i,
//        h_{i+1}^2 / (h_{i+1}^2 + h_i^2) for 2j > d_i,
//   S = sum b^i_{j,k} C^i_{j,k} / sum b^i_{j,k}       (no central point).
// The surface interpolates each ribbon's boundary row and its cross-boundary derivative
// (3 (C_{j,1} - C_{j,0}) in h for l = 2), so it is G1 with every ribbon.
//
// Control points are stored once: ribbon i's last boundary point is ribbon i+1's first
// (the network vertex). Storage order: for each side i, boundary row j = 0..d_i-1, then rows
// k = 1..l_i-1 with j = 0..d_i.
//
// The parts: the domain (ConcavePolygonDomain), the parameterization (mean value coordinates,
// core/param/mean_value.hpp), the ribbons in homogeneous Bernstein form (ribbon_powers.hpp: the
// 0/0 of s_i on the sides away from ribbon i becomes the exact one-sided limit), the blend
// (blend.hpp: ribbon_mu and the squared corner weights), and at the domain vertices, where the
// weights are 0/0, the corner limits (vertex_limits.hpp).
#pragma once

#include <cstdint>
#include <vector>

#include "core/domain/concave_polygon.hpp"
#include "core/param/mean_value.hpp"
#include "core/patch/gb/ribbon.hpp"
#include "core/patch/gb/ribbon_local.hpp"
#include "core/patch/gb/ribbon_powers.hpp"
#include "core/patch/patch.hpp"

namespace pl {

class GBRibbonPatch final : public PatchType<GBRibbonPatch> {
 public:
  static constexpr const char* kType = "gb-ribbons";  // the scene-format type name
  // The largest ribbon degree and layer count the gb-ribbons format accepts (the codec's limits;
  // the elevation functions refuse to go beyond them).
  static constexpr int kMaxDegree = kMaxRibbonDegree, kMaxLayers = kMaxRibbonLayers;
  // The most sides (the parameterization's limit; evaluate() keeps its arrays on the stack).
  static constexpr int kMaxSides = MeanValueParameters::kMaxSides;

  // ribbons[i][k][j] = C^i_{j,k}. Throws std::invalid_argument for more than kMaxSides sides,
  // sizes that do not match the domain, l < 2, degree < 1, ribbons that do not share their
  // corner points, straight domain corners, or a domain over which the mean value coordinates
  // make the blend singular.
  GBRibbonPatch(ConcavePolygonDomain domain,
                const std::vector<std::vector<std::vector<Vec3>>>& ribbons);

  const Domain& domain() const override { return domain_; }
  const ConcavePolygonDomain& polygon() const { return domain_; }
  ControlPointKind kind(std::size_t k) const override;
  void basis(Vec2 x, std::span<Jet> out) const override;
  // sum b C / sum b summed directly (power tables per ribbon, no heap allocation per sample);
  // equal to the basis() sum up to rounding, and the basis() corner limits at the vertices.
  SurfaceJet evaluate(Vec2 x) const override;
  // evaluate() at many points. A convex face of a network shares its basis with the faces of the
  // same domain and layout (the convex faces at one density: shared_basis.hpp) and sums
  // phi_k C_k over it: the basis kept for a block of points that another patch asked for before,
  // else evaluated here, the same numbers either way. A concave face, and a face evaluated on its
  // own (under a SharedBasisBypass), runs evaluate() a block of points at a time in SIMD lanes:
  // evaluate()'s numbers bit for bit. The two agree to rounding.
  void evaluate_many(std::span<const Vec2> xs, std::span<SurfaceJet> out) const override;
  std::vector<BezierCurve> boundary_curves() const override;

  int sides() const { return static_cast<int>(degree_.size()); }
  int degree(int side) const { return degree_.at(side); }
  int layers(int side) const { return layers_.at(side); }
  // Storage index of C^side_{j,k}.
  std::size_t index(int side, int j, int k) const;
  const Vec3& point(int side, int j, int k) const { return points_[index(side, j, k)]; }
  std::vector<std::vector<std::vector<Vec3>>> ribbons() const;

  // The sides i of the domain where the mean value coordinates of vertices i-1 and i sum to 0 or
  // less somewhere inside (sampled; none for a convex domain), with such a point each if
  // `where` is given. A ribbon with d_i > l_i has a pole there; one with d_i <= l_i has none.
  static std::vector<int> sides_without_positive_pair(const ConcavePolygonDomain& domain,
                                                      std::vector<Vec2>* where = nullptr);

 private:
  // Throws if a blend has a pole or the sum of blends is not positive inside the domain.
  void check_parameterisation() const;
  // The blends b^i_{j,k} at x (not a vertex), unnormalised, and their sum.
  Jet blends(Vec2 x, std::span<Jet> out) const;
  // The surface at one sample (T = double) or one per lane (out[b]), not at a vertex; returns
  // the lanes on a side where a ribbon's D vanishes, left to the scalar path (none for double,
  // which sums those limits itself).
  template <class T>
  uint32_t surface_at(const T& u, const T& v, SurfaceJet* out) const;
  uint32_t evaluate_lanes(const Lane& u, const Lane& v, SurfaceJet* out) const;
  uint32_t evaluate_lanes(const WideLane& u, const WideLane& v, SurfaceJet* out) const;
  // evaluate_many() through the shared basis.
  void evaluate_shared(std::span<const Vec2> xs, std::span<SurfaceJet> out) const;
  template <class T>
  uint32_t quotient_form(const RibbonLocalOf<T>& L, const T* origin, VectorJet<T, 4>& S) const;
  template <class V>
  void evaluate_blocks(std::span<const Vec2> xs, std::span<SurfaceJet> out) const;

  ConcavePolygonDomain domain_;
  MeanValueParameters params_;
  std::vector<int> degree_, layers_;
  bool convex_ = false;  // every corner of the domain turns left (quotient_form() applies)
  std::vector<std::size_t> offset_;
};

}  // namespace pl
