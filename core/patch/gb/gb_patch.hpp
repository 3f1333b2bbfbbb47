// Convex Generalized Bézier (GB) patch with a central point (Várady, Salvi, Karikó 2016), with
// the conventions of the transfinite library (tests/data/gb/README.md):
//   S(x) = sum_i sum_{j=0..d} sum_{k<l} mu^i_{j,k} B^d_j(s_i) B^d_k(h_i) P^i_{j,k} + B_0(x) C_0,
// over the regular n-gon (ConvexPolygonDomain::regular), l = ceil(d/2) layers per ribbon.
// The parts, as the paper has them: the domain; the parameterization (s_i, h_i from Wachspress
// coordinates, core/param/wachspress.hpp); the ribbons (ribbon.hpp); the blend, mu with the
// corner weights alpha and beta (blend.hpp); the central point C_0 takes the deficiency
// B_0 = 1 - sum of all other weights.
//
// Control points are stored once, in .gbp order: C_0, then for k = 0..l-1, i = 0..n-1,
// j = k..d-1-k the point P^i_{j,k}; the other entries of a ribbon's grid are the shared corner
// block points of the neighbouring sides (P^i_{j,k} = P^{i-1}_{d-k,j} for j < k and
// P^{i+1}_{k,d-j} for j > d-1-k). Ribbon i for d = 3 (l = 2), "o" stored with side i:
//
//   k = 1   a       o       b       c      a = P^{i-1}_{2,0}, b = P^{i+1}_{1,1}, c = P^{i+1}_{1,0}
//   k = 0   o-------o-------o-------e      e = P^{i+1}_{0,0}, the corner point at vertex i
//         v_{i-1}                  v_i     (row k = 0 is side i's boundary curve)
//
// Singular points: the corner weights are 0/0 at the domain vertices (and for n = 3 s_i at the
// opposite vertex). There the value is the corner control point and the derivatives are exact
// limits along the ray to the centre (vertex_limits.hpp). s_i and h_i are computed in forms
// that stay defined on the far sides, so nothing else is singular.
//
// Evaluation: one template per quantity (the surface, one basis function, the central weight)
// runs one sample (Jet) or a block of samples, one per SIMD lane (core/math/lanes.hpp), so the
// batched paths give the scalar paths' numbers bit for bit.
#pragma once

#include <cstdint>

#include "core/domain/convex_polygon.hpp"
#include "core/param/wachspress.hpp"
#include "core/patch/gb/blend.hpp"
#include "core/patch/gb/ribbon.hpp"
#include "core/patch/patch.hpp"

namespace pl {

// The .gbp stored index of P^i_{j,k} (any j in 0..d, k in 0..l-1, i taken modulo n) of a net of
// n sides and degree d: the one rule of the .gbp point order, for a patch (GBPatch::index) and
// for a plain net without one (so for any n, also beyond GBPatch::kMaxSides).
std::size_t gb_net_index(int sides, int degree, int i, int j, int k);

class GBPatch final : public PatchType<GBPatch> {
 public:
  static constexpr int kMaxSides = WachspressParameters::kMaxSides;
  static constexpr int kMaxDegree = 20;
  static constexpr const char* kType = "gb";  // the scene-format type name

  // Throws std::invalid_argument for n outside 3..kMaxSides, d outside 1..kMaxDegree or a
  // wrong point count.
  GBPatch(int sides, int degree, std::vector<Vec3> points);

  static int layers(int degree) { return (degree + 1) / 2; }
  static std::size_t point_count(int sides, int degree);

  const Domain& domain() const override { return domain_; }
  ControlPointKind kind(std::size_t k) const override;
  void set_control_point(std::size_t k, const Vec3& p) override;
  void basis(Vec2 x, std::span<Jet> out) const override;
  SurfaceJet evaluate(Vec2 x) const override;
  // Blocks of samples through the lane form of evaluate() (bit for bit its numbers).
  void evaluate_many(std::span<const Vec2> xs, std::span<SurfaceJet> out) const override;
  // Blocks of samples through the lane form of influence_at() (bit for bit its numbers).
  void influence(std::size_t k, std::span<const Vec2> xs, std::span<Jet> out) const override;
  // phi_k at one point: one basis function, without the others.
  Jet influence_at(std::size_t k, Vec2 x) const;
  // Side i: the layer-0 row P^i_{0..d,0}, from vertex i-1 to vertex i.
  std::vector<BezierCurve> boundary_curves() const override;

  int sides() const { return n_; }
  int degree() const { return d_; }
  int layers() const { return l_; }
  const ConvexPolygonDomain& polygon() const { return domain_; }
  const WachspressParameters& parameters() const { return params_; }
  // Stored index of P^i_{j,k} for any j in 0..d, k in 0..l-1 (i taken modulo n): gb_net_index.
  std::size_t index(int i, int j, int k) const;
  const Vec3& point(int i, int j, int k) const { return points_[index(i, j, k)]; }
  // The weight rule of grid position (j, k) (central_mu); the same for every ribbon.
  Mu mu(int j, int k) const { return mu_[k * (d_ + 1) + j]; }

 private:
  struct Occurrence {  // a grid position (i, j, k) where a stored point has a non-zero weight
    int i, j, k;
  };
  // The sides whose s, h a set of ribbons needs, and which of them need alpha_i (a ribbon's
  // weighted points need alpha_i and, for beta_i, alpha_{i+1}).
  struct Needs {
    SideMask sides, alphas;
  };
  Needs needs(SideMask ribbons, SideMask weighted) const;

  // The templates of one sample (T = double) or a block (T = Lane, WideLane).
  template <class T>
  void parameters_at(const T& u, const T& v, JetOf<T>* s, JetOf<T>* h, SideMask sides) const;
  template <class T>
  VectorJet<T> surface_at(const T& u, const T& v) const;
  template <class T>
  JetOf<T> weight_at(std::size_t k, const T& u, const T& v) const;
  template <class T>
  JetOf<T> central_weight_at(const T& u, const T& v) const;

  // surface_at and weight_at at kLanes (kWideLanes) points (u[b], v[b]), written to
  // out[0..count); the WideLane forms only where wide_lanes() holds.
  void evaluate_lanes(const Lane& u, const Lane& v, SurfaceJet* out, int count) const;
  void evaluate_lanes(const WideLane& u, const WideLane& v, SurfaceJet* out, int count) const;
  void influence_lanes(std::size_t k, const Lane& u, const Lane& v, Jet* out, int count) const;
  void influence_lanes(std::size_t k, const WideLane& u, const WideLane& v, Jet* out,
                       int count) const;
  // Runs `lanes(u, v, first, count)` on blocks of xs (points at a domain vertex replaced by the
  // interior point), then `at_vertex(p)` for each of those points; V: the lane type.
  template <class V, class Lanes, class AtVertex>
  void for_lane_blocks(std::span<const Vec2> xs, Lanes&& lanes, AtVertex&& at_vertex) const;

  // Away from the domain vertices: the surface, phi_k, and every phi_k.
  SurfaceJet evaluate_regular(Vec2 x) const;
  Jet influence_regular(std::size_t k, Vec2 x) const;
  void basis_regular(Vec2 x, std::span<Jet> out) const;
  int vertex_at(Vec2 x) const;  // index of the domain vertex x sits on, or -1
  void update_rows(std::size_t k);

  int n_, d_, l_;
  ConvexPolygonDomain domain_;
  WachspressParameters params_;
  double vertex_distance_ = 0;  // a lower bound of |vertex| - kVertexRadius
  std::vector<Mu> mu_;          // [k * (d+1) + j]
  std::vector<uint32_t> grid_;  // [(i * l + k) * (d+1) + j] -> stored index
  std::vector<std::vector<Occurrence>> occurrences_;
  // The sides phi_k needs, per stored point k: those of the ribbons where it has a non-zero
  // weight, and of the corner weights where that weight is alpha_i or beta_i.
  std::vector<Needs> needs_;
  RibbonRows rows_;
};

}  // namespace pl
