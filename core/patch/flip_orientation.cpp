#include "core/patch/flip_orientation.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>

#include "core/patch/bezier_patch.hpp"
#include "core/patch/bspline_patch.hpp"
#include "core/patch/catmull_clark_patch.hpp"
#include "core/patch/coons_network_patch.hpp"
#include "core/patch/gb/gb_patch.hpp"
#include "core/patch/gb/gb_ribbon_patch.hpp"
#include "core/patch/gregory_quad.hpp"
#include "core/patch/gregory_tri.hpp"
#include "core/patch/hermite_patch.hpp"
#include "core/patch/interpolating_patch.hpp"
#include "core/patch/nurbs_patch.hpp"

namespace pl {

namespace {

using Index = std::vector<std::size_t>;

// The grid of nu x nv points (i * nv + j) seen with u and v swapped: nv x nu, (j, i) at j * nu + i.
Index transposed(std::size_t nu, std::size_t nv) {
  Index old(nu * nv);
  for (std::size_t i = 0; i < nv; ++i)
    for (std::size_t j = 0; j < nu; ++j) old[i * nu + j] = j * nv + i;
  return old;
}

template <class T>
std::vector<T> permuted(const std::vector<T>& values, const Index& old) {
  std::vector<T> out;
  out.reserve(old.size());
  for (std::size_t k : old) out.push_back(values.at(k));
  return out;
}

// The Gregory patches: new side s is old side (last - s) reversed, so boundary point j of side s
// is old boundary point (row - j) of side (last - s) and twin k is old twin 1 - k.
template <class P>
Index gregory_flip(int sides, int row) {
  Index old(P::kPointCount);
  for (int s = 0; s < sides; ++s) {
    const int o = sides - 1 - s;
    for (int j = 0; j < row; ++j) old[P::boundary_index(s, j)] = P::boundary_index(o, row - j);
    for (int k = 0; k < 2; ++k) old[P::twin_index(s, k)] = P::twin_index(o, 1 - k);
  }
  return old;
}

// GB sides: with vertex m mapped to old vertex -m (a mirror symmetry of the domain), side i, from
// vertex i-1 to vertex i, is old side 1-i run backwards.
int mirrored_side(int i, int n) {
  return ((1 - i) % n + n) % n;
}

FlippedPatch flip_gb(const GBPatch& p) {
  const int n = p.sides(), d = p.degree(), l = p.layers();
  Index old{0};  // the central point stays
  for (int k = 0; k < l; ++k)
    for (int i = 0; i < n; ++i)
      for (int j = k; j <= d - 1 - k; ++j) old.push_back(p.index(mirrored_side(i, n), d - j, k));
  auto flipped = std::make_unique<GBPatch>(n, d, permuted(p.control_points(), old));
  return {std::move(flipped), std::move(old)};
}

FlippedPatch flip_gb_ribbons(const GBRibbonPatch& p) {
  const int n = p.sides();
  std::vector<Vec2> vertices;
  for (int m = 0; m < n; ++m) {
    const Vec2 v = p.polygon().vertex(-m);  // index taken modulo n
    vertices.emplace_back(-v.x, v.y);
  }
  const auto ribbons = p.ribbons();
  std::vector<std::vector<std::vector<Vec3>>> flipped_ribbons(n);
  for (int i = 0; i < n; ++i) {
    flipped_ribbons[i] = ribbons[mirrored_side(i, n)];
    for (auto& row : flipped_ribbons[i]) std::reverse(row.begin(), row.end());
  }
  auto flipped =
      std::make_unique<GBRibbonPatch>(ConcavePolygonDomain(std::move(vertices)), flipped_ribbons);
  Index old(p.size());
  for (int i = 0; i < n; ++i) {
    const int o = mirrored_side(i, n), d = p.degree(o);
    for (int k = 0; k < p.layers(o); ++k)
      for (int j = 0; j <= d; ++j) old[flipped->index(i, j, k)] = p.index(o, d - j, k);
  }
  return {std::move(flipped), std::move(old)};
}

FlippedPatch flip_coons(const CoonsNetworkPatch& p) {
  const std::size_t ns = p.ns(), nt = p.nt();
  // Nodes transposed; r_s and r_t trade places, r and r_st stay.
  constexpr int kSwap[4] = {0, 2, 1, 3};
  Index old(p.size());
  const Index nodes = transposed(ns, nt);
  for (std::size_t n = 0; n < nodes.size(); ++n)
    for (int q = 0; q < 4; ++q) old[n * 4 + q] = nodes[n] * 4 + kSwap[q];
  auto flipped = std::make_unique<CoonsNetworkPatch>(
      nt, ns, p.t(), p.s(), permuted(p.control_points(), old), p.lengths());
  return {std::move(flipped), std::move(old)};
}

template <class P>
FlippedPatch same_type(const Patch& p, Index old) {
  return {std::make_unique<P>(permuted(p.control_points(), old)), std::move(old)};
}

}  // namespace

bool can_flip_orientation(const Patch& p) {
  return dynamic_cast<const BezierPatch*>(&p) || dynamic_cast<const BSplinePatch*>(&p) ||
         dynamic_cast<const NurbsPatch*>(&p) || dynamic_cast<const InterpolatingPatch*>(&p) ||
         dynamic_cast<const HermitePatch*>(&p) || dynamic_cast<const CoonsNetworkPatch*>(&p) ||
         dynamic_cast<const GregoryQuadPatch*>(&p) || dynamic_cast<const GregoryTriPatch*>(&p) ||
         dynamic_cast<const GBPatch*>(&p) || dynamic_cast<const GBRibbonPatch*>(&p) ||
         dynamic_cast<const CatmullClarkPatch*>(&p);
}

FlippedPatch flipped_orientation(const Patch& patch) {
  if (const auto* p = dynamic_cast<const BezierPatch*>(&patch)) {
    Index old = transposed(p->degree_u() + 1, p->degree_v() + 1);
    return {std::make_unique<BezierPatch>(p->degree_v(), p->degree_u(),
                                          permuted(p->control_points(), old)),
            std::move(old)};
  }
  if (const auto* p = dynamic_cast<const BSplinePatch*>(&patch)) {
    const SplineGrid& g = p->grid();
    Index old = transposed(g.nu(), g.nv());
    return {std::make_unique<BSplinePatch>(g.q(), g.p(), g.knots_v(), g.knots_u(), g.nv(), g.nu(),
                                           permuted(p->control_points(), old)),
            std::move(old)};
  }
  if (const auto* p = dynamic_cast<const NurbsPatch*>(&patch)) {
    const SplineGrid& g = p->grid();
    Index old = transposed(g.nu(), g.nv());
    return {std::make_unique<NurbsPatch>(g.q(), g.p(), g.knots_v(), g.knots_u(), g.nv(), g.nu(),
                                         permuted(p->control_points(), old),
                                         permuted(p->weights(), old)),
            std::move(old)};
  }
  if (dynamic_cast<const InterpolatingPatch*>(&patch))
    return same_type<InterpolatingPatch>(patch, transposed(4, 4));
  // r(u, v) = F(u) Q F(v)^T, so r(v, u) has the matrix Q^T.
  if (dynamic_cast<const HermitePatch*>(&patch))
    return same_type<HermitePatch>(patch, transposed(4, 4));
  if (const auto* p = dynamic_cast<const CoonsNetworkPatch*>(&patch)) return flip_coons(*p);
  if (dynamic_cast<const GregoryQuadPatch*>(&patch))
    return same_type<GregoryQuadPatch>(patch, gregory_flip<GregoryQuadPatch>(4, 3));
  if (dynamic_cast<const GregoryTriPatch*>(&patch))
    return same_type<GregoryTriPatch>(patch, gregory_flip<GregoryTriPatch>(3, 4));
  if (const auto* p = dynamic_cast<const GBPatch*>(&patch)) return flip_gb(*p);
  if (const auto* p = dynamic_cast<const GBRibbonPatch*>(&patch)) return flip_gb_ribbons(*p);
  if (const auto* p = dynamic_cast<const CatmullClarkPatch*>(&patch)) {
    // Every face loop reversed: each face is seen from the other side.
    std::vector<std::vector<int>> faces = p->limit().faces();
    for (auto& f : faces) std::reverse(f.begin(), f.end());
    Index old(p->size());
    std::iota(old.begin(), old.end(), std::size_t{0});
    return {std::make_unique<CatmullClarkPatch>(p->control_points(), std::move(faces)),
            std::move(old)};
  }
  throw std::invalid_argument("cannot flip the orientation of a \"" + patch.type() +
                              "\" patch (its pieces are built for one side)");
}

}  // namespace pl
