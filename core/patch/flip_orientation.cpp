#include "core/patch/flip_orientation.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <type_traits>
#include <utility>

#include "core/patch/patch_types.hpp"

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

FlippedPatch flip_type(const GBPatch& p) {
  const int n = p.sides(), d = p.degree(), l = p.layers();
  Index old{0};  // the central point stays
  for (int k = 0; k < l; ++k)
    for (int i = 0; i < n; ++i)
      for (int j = k; j <= d - 1 - k; ++j) old.push_back(p.index(mirrored_side(i, n), d - j, k));
  auto flipped = std::make_unique<GBPatch>(n, d, permuted(p.control_points(), old));
  return {std::move(flipped), std::move(old)};
}

FlippedPatch flip_type(const GBRibbonPatch& p) {
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

FlippedPatch flip_type(const CoonsNetworkPatch& p) {
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

FlippedPatch flip_type(const BezierPatch& p) {
  Index old = transposed(p.degree_u() + 1, p.degree_v() + 1);
  return {
      std::make_unique<BezierPatch>(p.degree_v(), p.degree_u(), permuted(p.control_points(), old)),
      std::move(old)};
}

FlippedPatch flip_type(const BSplinePatch& p) {
  const SplineGrid& g = p.grid();
  Index old = transposed(g.nu(), g.nv());
  return {std::make_unique<BSplinePatch>(g.q(), g.p(), g.knots_v(), g.knots_u(), g.nv(), g.nu(),
                                         permuted(p.control_points(), old)),
          std::move(old)};
}

FlippedPatch flip_type(const NurbsPatch& p) {
  const SplineGrid& g = p.grid();
  Index old = transposed(g.nu(), g.nv());
  return {
      std::make_unique<NurbsPatch>(g.q(), g.p(), g.knots_v(), g.knots_u(), g.nv(), g.nu(),
                                   permuted(p.control_points(), old), permuted(p.weights(), old)),
      std::move(old)};
}

FlippedPatch flip_type(const InterpolatingPatch& p) {
  return same_type<InterpolatingPatch>(p, transposed(4, 4));
}

// r(u, v) = F(u) Q F(v)^T, so r(v, u) has the matrix Q^T.
FlippedPatch flip_type(const HermitePatch& p) {
  return same_type<HermitePatch>(p, transposed(4, 4));
}

FlippedPatch flip_type(const GregoryQuadPatch& p) {
  return same_type<GregoryQuadPatch>(p, gregory_flip<GregoryQuadPatch>(4, 3));
}

FlippedPatch flip_type(const GregoryTriPatch& p) {
  return same_type<GregoryTriPatch>(p, gregory_flip<GregoryTriPatch>(3, 4));
}

// Every face loop reversed: each face is seen from the other side.
FlippedPatch flip_type(const CatmullClarkPatch& p) {
  std::vector<std::vector<int>> faces = p.limit().faces();
  for (auto& f : faces) std::reverse(f.begin(), f.end());
  Index old(p.size());
  std::iota(old.begin(), old.end(), std::size_t{0});
  return {std::make_unique<CatmullClarkPatch>(p.control_points(), std::move(faces)),
          std::move(old)};
}

// The types that are not flipped as a patch: a composite's construction fixes which piece lies on
// which side, and a network face (ribbons, GB with interior control) is the network's to orient.
struct NotFlippable {};
template <OneOf<PairJoinPatch, GapFillPatch, GBInteriorPatch, RibbonPatch> T>
NotFlippable flip_type(const T&) {
  return {};
}

// Every registered type has a flip_type overload (else the visits below do not compile); its
// return type says whether the type flips.
template <class T>
constexpr bool kFlippable =
    !std::is_same_v<decltype(flip_type(std::declval<const T&>())), NotFlippable>;

}  // namespace

bool can_flip_orientation(const Patch& patch) {
  return visit_patch_type(patch, []<class T>(const T&) { return kFlippable<T>; });
}

FlippedPatch flipped_orientation(const Patch& patch) {
  return visit_patch_type(patch, []<class T>(const T& p) -> FlippedPatch {
    if constexpr (kFlippable<T>)
      return flip_type(p);
    else
      throw std::invalid_argument("cannot flip the orientation of a \"" + p.type() +
                                  "\" patch (its pieces are built for one side)");
  });
}

}  // namespace pl
