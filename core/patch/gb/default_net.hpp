// Default positions of the control points of a convex GB patch that a designer did not place.
//
// The GB papers (Várady, Salvi, Karikó, CGF 2016; Várady, Salvi, Kovács, CAGD 2017) place the
// interior points "automatically by a special degree elevation algorithm" (CGF 2016 abstract);
// the rule itself is not public in a form we could retrieve. The only published code we found is
// the authors' gb-center (github.com/salvipeter/gb-center), for cubic patches: each corner twist
// point is the parallelogram point of its two boundary neighbours and C_0 is the mean of those
// twists. We generalise that to any n and d with rules that are affine combinations (so a
// planar net stays planar, and the patch is that plane) and that reproduce, for n = 4, the
// tensor-product nets the classical Coons constructions reproduce:
//
// Ring r of the net: the points at grid distance r from the boundary (ring 0 = layer 0, the
// boundary, which must be placed; ring 1 = the cross-boundary row). In ribbon i's grid Q_{j,k}
// (j along side i, k inwards), E_{j,k} = Q_{j,0} + k (Q_{j,1} - Q_{j,0}) is the linear
// extrapolation of the ribbon's first-order (G1) data: the degree-d form of a ribbon linear in h.
//  1. Ring 1 (d >= 3): corner twist Q_{1,1} = Q_{1,0} + Q_{0,1} - Q_{0,0} (parallelogram, as
//     gb-center); the other points Q_{j,0} + the cross vectors Q_{.,1} - Q_{.,0} of the two
//     twists interpolated linearly in j.
//  2. Corner blocks, rings >= 2 (the l x l block where sides i-1 and i meet, ribbon i's j < l):
//     the Boolean sum of the two ribbons' extrapolations minus their bilinear common part,
//     Q_{j,k} = E_{j,k} + (Q_{0,k} + j (Q_{1,k} - Q_{0,k})) - T_{j,k}, T the bilinear
//     extrapolation of Q_{0..1,0..1} (the discrete analogue of a bilinearly blended Coons patch).
//  3. Middle column of even d (j = d/2, rings >= 2, owned by ribbon i alone): the Boolean sum of
//     the extrapolation and the row's linear interpolation between its two corner-block
//     neighbours, Q_{m,k} = E_{m,k} + (Q_{m-1,k} + Q_{m+1,k})/2 - (E_{m-1,k} + E_{m+1,k})/2.
//  4. C_0: odd d = 2m+1: the mean of the n innermost corner points P^i_{m,m} (gb-center's rule
//     for d = 3). Even d = 2m: the discrete Coons stencil around the tensor-product middle,
//     C_0 = (2/n) sum_i P^i_{m,m-1} - (1/n) sum_i P^i_{m-1,m-1}.
// What holds (tests/core/gb_default_net_test.cpp): a net whose placed points lie on a plane
// gets defaults on that plane; for n = 4 with rings 0 and 1 taken from the degree-(d,d) net of
// S(u,v) = f(u) + v g(u) + h(v) + u k(v) (every bilinearly blended Coons patch has this form),
// the defaults are that net, so the GB patch is that tensor-product patch; from the boundary
// alone the translational nets f(u) + h(v) are reproduced.
// Caveat: rule 2 extrapolates derivative data, the corner twist entering with weight j k, so a
// wobbly ring 1 is amplified towards the middle. On the reference models (tests/data/gb)
// the default surface from rings 0 and 1 stays within 0.54 % of the designed cagd86 surface and
// 0.32 .. 4.2 % of the dome models (largest distance over the reference samples, relative to the
// net's diagonal); on the tp4 nets, whose heights are random numbers, it is 4e-16 (d = 3,
// nothing to default but C_0, which has no weight) to 20 % (d = 6)
// (GBDefaultNet.ReferenceModelsFromRings0And1 prints and bounds them).
#pragma once

#include <span>
#include <vector>

#include "core/patch/gb/gb_patch.hpp"

namespace pl {

// The rules below on a plain net in .gbp order (GBPatch::point_count(n, d) points, any n >= 3):
// every point with !placed[k] is moved to its default position. Throws like gb_default_net.
std::vector<Vec3> gb_default_points(int sides, int degree, std::vector<Vec3> points,
                                    std::span<const bool> placed);

// Ring of stored point k of a GB patch of n sides and degree d: 0 for the boundary, r for the
// points at grid distance r from it, -1 for the central point C_0 (stored index 0).
int gb_ring(int sides, int degree, std::size_t k);

// The patch with every stored point k with !placed[k] moved to its default position; placed
// points are kept. Throws std::invalid_argument if placed has the wrong size or a boundary point
// is not placed.
GBPatch gb_default_net(const GBPatch& patch, std::span<const bool> placed);

// Keeps the rings 0 .. kept_rings-1 (1: the boundary only, 2: boundary and cross-boundary row)
// and gives every other point, C_0 included, its default position. kept_rings >= 1.
GBPatch gb_default_net(const GBPatch& patch, int kept_rings = 2);

}  // namespace pl
