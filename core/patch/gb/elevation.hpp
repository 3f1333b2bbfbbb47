// Degree elevation d -> d+1 of a convex GB patch (core/patch/gb/gb_patch.hpp).
//
// Exact elevation does not exist for n != 4: the GB surface is linear in its control points, and
// the least-squares fit of the degree-(d+1) basis to each degree-d basis function over ~1000
// domain samples leaves residuals of 2e-4 .. 9e-3 (largest over the samples, basis functions
// are <= 1; n = 3, 5, 6, 7; d = 2..7; two sample sets agree within a factor of 2; full column
// rank, R conditioning below 1e4), so no degree-(d+1) net reproduces a general degree-d surface.
// For n = 4 the same fit is exact to rounding (1.3e-15 measured), because the patch is the
// tensor-product Bézier patch. GBElevation.ExactElevationExistsOnlyForFourSides
// (tests/core/gb_elevation_test.cpp) prints the table and asserts these bounds.
//
// So this is the papers' elevation ("linear and bilinear combinations; modifies the surface
// interior"): every ribbon grid P^i_{j,k} is elevated as a tensor-product Bézier net,
//   Q^i_{j,k} = sum_{a,b in {0,1}} w_a(j) w_b(k) P^i_{j-a,k-b},
//   w_1(t) = t/(d+1), w_0(t) = 1 - t/(d+1),
// rows k = 0 .. l'-1 of the new net (l' = ceil((d+1)/2)). For even d = 2m the new innermost row
// needs the old row m, which a ribbon does not own: it is the tensor-product middle row, read
// through the neighbouring ribbons' middle columns, P^i_{j,m} = P^{i-1}_{m,j} (j < m),
// P^i_{m,m} = C_0, P^i_{j,m} = P^{i+1}_{m,d-j} (j > m). With these rows two ribbons that share
// a corner block compute the same points (the block elevates from the shared old block), so
// the stored net is consistent. The new C_0 makes the new patch pass through the old patch's
// centre point S(0, 0) (the middle-point interpolation of CGF 2016) for every n and d (measured
// 1.2e-15 relative, n = 3..16, d = 2..19): C_0's weight at the centre is >= 0.11 for n != 4 and
// >= 0.03 for n = 4 with even d+1. For n = 4 with odd d+1 C_0 has no weight at all; it takes the
// default-net position (default_net.hpp, rule 4) and the centre is kept by the exact
// tensor-product elevation. The interior of random nets moves by 0.1 .. 3.3 % of the net's
// diagonal (n = 3, 5..8, d = 2..7). Against two other rules for C_0 (keeping the old C_0, the
// default-net rule 4), the centre rule gave the smallest largest move in 28 of those 30 cases
// and was never more than 5 % above the better of the two
// (GBElevation.InteriorDeviationAndTheCentralPointRule).
// Kept exactly: every boundary curve (row 0 elevates as a Bézier curve) and, for d >= 3, every
// ribbon's cross-boundary derivative (rows 0 and 1 elevate as the degree-(d+1) form of the same
// first-order data), so the surface's first derivatives along the boundary; for n = 4 the whole
// surface (tensor-product elevation). Not for d = 2 and n != 4: our quadratic variant has no
// ribbon row 1 (its cross derivative comes from C_0 and the neighbouring sides through rational
// weights, which a cubic row 1 cannot reproduce); there only the boundary curves are kept.
#pragma once

#include "core/patch/gb/gb_patch.hpp"

namespace pl {

// The degree-(d+1) patch. Throws std::invalid_argument for d >= GBPatch::kMaxDegree or d < 2
// (degree 1 has no ribbon rows to elevate into the quadratic variant's corner rule).
GBPatch gb_elevate(const GBPatch& patch);

}  // namespace pl
