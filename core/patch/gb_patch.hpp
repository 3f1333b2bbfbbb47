// Convex Generalized Bézier (GB) patch (Várady, Salvi, Karikó 2016), with the conventions of the
// transfinite library and ../shared/reference/gb/README.md:
//   S(x) = sum_i sum_{j=0..d} sum_{k<l} mu^i_{j,k} B^d_j(s_i) B^d_k(h_i) P^i_{j,k} + B_0(x) C_0,
// over the regular n-gon (ConvexPolygonDomain::regular), l = ceil(d/2) layers per ribbon.
//   mu: alpha_i = h_{i-1}/(h_{i-1}+h_i) for j < 2, beta_i = h_{i+1}/(h_{i+1}+h_i) for j > d-2
//   (rows k < 2 only), 1/2 on the diagonals j = k and j = d-k, 0 beyond them, 1 elsewhere;
//   the central point C_0 takes the deficiency B_0 = 1 - sum of all other weights.
// Degree 1 and 2 (the quadratic variant): the alpha/beta rule is not applied, because the 2x2
// corner blocks of one side overlap and would give the middle boundary point a rational weight
// (README "Degree caveat"). The diagonal rule then gives each corner point 1/2 from both ribbons,
// which interpolates the boundary for every n (on side i the neighbour's corner term equals
// B^d_d(s_i) exactly) and reproduces the biquadratic tensor-product patch for n = 4.
//
// Control points are stored once, in .gbp order: C_0, then for k = 0..l-1, i = 0..n-1,
// j = k..d-1-k the point P^i_{j,k}; the other entries of a ribbon's grid are the shared corner
// block points of the neighbouring sides.
//
// Singular points: the corner weights alpha, beta are 0/0 at the domain vertices (and for n = 3
// s_i at the opposite vertex). There the value is the corner control point and the derivatives
// are exact limits along the ray to the centre (first derivatives do not depend on the
// direction; second derivatives in general do). s_i and h_i are computed in forms that stay
// defined on the far sides (PolygonParameters), so nothing else is singular.
#pragma once

#include <array>
#include <cstdint>

#include "core/domain/convex_polygon.hpp"
#include "core/param/polygon_parameters.hpp"
#include "core/patch/patch.hpp"

namespace pl {

class GBPatch final : public Patch {
 public:
  static constexpr int kMaxSides = PolygonParameters::kMaxSides;
  static constexpr int kMaxDegree = 20;

  // Throws std::invalid_argument for n outside 3..16, d outside 1..20 or a wrong point count.
  GBPatch(int sides, int degree, std::vector<Vec3> points);

  static int layers(int degree) { return (degree + 1) / 2; }
  static std::size_t point_count(int sides, int degree);

  std::unique_ptr<Patch> clone() const override { return std::make_unique<GBPatch>(*this); }
  std::string type() const override { return "gb"; }
  const Domain& domain() const override { return domain_; }
  ControlPointKind kind(std::size_t k) const override;
  void set_control_point(std::size_t k, const Vec3& p) override;
  void basis(Vec2 x, std::span<Jet> out) const override;
  SurfaceJet evaluate(Vec2 x) const override;
  // Blocks of kLanes points through evaluate_lanes (tests check it equals evaluate()).
  void evaluate_many(std::span<const Vec2> xs, std::span<SurfaceJet> out) const override;
  // Blocks of kLanes points through influence_lanes (k > 0; tests check it equals influence_at).
  void influence(std::size_t k, std::span<const Vec2> xs, std::span<Jet> out) const override;
  // phi_k at one point by the scalar path: the reference of the batched influence().
  Jet influence_at(std::size_t k, Vec2 x) const;
  // Side i: the layer-0 row P^i_{0..d,0}, from vertex i-1 to vertex i.
  std::vector<BezierCurve> boundary_curves() const override;

  int sides() const { return n_; }
  int degree() const { return d_; }
  int layers() const { return l_; }
  const ConvexPolygonDomain& polygon() const { return domain_; }
  // Stored index of P^i_{j,k} for any j in 0..d, k in 0..l-1 (i taken modulo n).
  std::size_t index(int i, int j, int k) const;
  const Vec3& point(int i, int j, int k) const { return points_[index(i, j, k)]; }

  enum class Mu : uint8_t { Zero, Half, One, Alpha, Beta };
  // The weight rule of grid position (j, k); the same for every ribbon.
  Mu mu(int j, int k) const { return mu_[k * (d_ + 1) + j]; }

 private:
  struct Local;  // per-point parameters, shared by evaluate, basis and influence
  // Parameters s, h of the ribbons whose bit is set in `ribbons`, and the corner weights of those
  // set in `weighted` (a subset of ribbons) with the h's they need.
  void local(Vec2 x, Local& out, uint32_t ribbons = ~0u, uint32_t weighted = ~0u) const;
  SurfaceJet evaluate_regular(Vec2 x) const;
  // evaluate_regular and influence_regular (k > 0) at kLanes points (u[b], v[b]) at once, one
  // per SIMD lane, written to out[0..count); the WideLane forms only where wide_lanes() holds.
  void evaluate_lanes(const Lane& u, const Lane& v, SurfaceJet* out, int count) const;
  void evaluate_lanes(const WideLane& u, const WideLane& v, SurfaceJet* out, int count) const;
  void influence_lanes(std::size_t k, const Lane& u, const Lane& v, Jet* out, int count) const;
  void influence_lanes(std::size_t k, const WideLane& u, const WideLane& v, Jet* out,
                       int count) const;
  template <class V>
  void evaluate_block(const V& u, const V& v, SurfaceJet* out, int count) const;
  template <class V>
  void influence_block(std::size_t k, const V& u, const V& v, Jet* out, int count) const;
  // Runs `lanes(u, v, first, count)` on blocks of xs (points at a domain vertex replaced by the
  // interior point), then `at_vertex(p)` for each of those points; V: the lane type.
  template <class V, class Lanes, class AtVertex>
  void for_lane_blocks(std::span<const Vec2> xs, Lanes&& lanes, AtVertex&& at_vertex) const;
  void basis_regular(Vec2 x, std::span<Jet> out) const;
  Jet influence_regular(std::size_t k, Vec2 x) const;
  void basis_vertex(int v, std::span<Jet> out) const;  // exact limits at domain vertex v
  int vertex_at(Vec2 x) const;  // index of the domain vertex x sits on, or -1
  double vertex_distance_ = 0;  // a lower bound of |vertex| - kVertexRadius

  int n_, d_, l_;
  ConvexPolygonDomain domain_;
  PolygonParameters params_;
  void update_relative(std::size_t k);

  std::vector<Mu> mu_;          // [k * (d+1) + j]
  std::vector<Vec3> relative_;  // P_k - C_0: evaluate() needs no central weight
  std::vector<uint32_t> grid_;  // [(i * l + k) * (d+1) + j] -> stored index
  // Where each stored point appears in the ribbon grids: (i, j, k) with a non-zero mu.
  struct Occurrence {
    int i, j, k;
  };
  std::vector<std::vector<Occurrence>> occurrences_;
  std::vector<uint32_t> ribbons_of_;   // bit i: the stored point has a non-zero weight in ribbon i
  std::vector<uint32_t> weighted_of_;  // bit i: ... and that weight is alpha_i or beta_i
  // evaluate_regular's dense tables, contiguous so the row sums need no index gather:
  // dense_[((i * 3 + g) * l + k) * (d+1) + j] = c * (P - C_0) for the grid point (i, j, k) if its
  // weight group is g (0: constant or beta, 1: alpha, 2: beta; c = 1/2 on the diagonals), else 0.
  // Group 0 includes beta because sum_i beta_i B_i = sum_i B_i - sum_i alpha_{i+1} B_i.
  std::vector<Vec3> dense_;
  // The j range [first, last] of the non-zero entries of group g, row k: span_[g * l + k].
  struct Span {
    int first, last;
  };
  std::vector<Span> span_;
  void fill_dense(std::size_t k);  // refreshes the entries of stored point k (all for k = 0)
};

}  // namespace pl
