// Degree elevation of one ribbon of a GB patch with independent ribbons
// (core/patch/gb/gb_ribbon_patch.hpp; Salvi & Várady SMI 2018: "degree elevation independently in
// the two parametric directions; adding a layer increases the degree by 2").
//
// Neither operation leaves the surface unchanged: the blend of C^i_{j,k} has its weight mu
// chosen by 2j against d_i and the patch divides by the sum of all blends, so a ribbon of another
// degree blends differently even where it represents the same polynomial (the interior moves by
// 1-2 % of the net's size on the test patches). Whether some other higher-degree net could
// reproduce the surface exactly was not measured for this patch type. What is kept exactly is
// what the patch interpolates: ribbon i's boundary curve and cross-boundary derivative, so the
// surface's position and first derivatives Su, Sv along every side (measured 2e-15 relative,
// tests/core/gb_ribbon_elevation_test.cpp).
#pragma once

#include "core/patch/gb/gb_ribbon_patch.hpp"

namespace pl {

// Ribbon `side` elevated along the side, d_i -> d_i + 1: every row elevated as a Bézier curve
// (C'_j = j/(d+1) C_{j-1} + (1 - j/(d+1)) C_j). Its end points, shared with the neighbouring
// ribbons, do not move. Throws std::invalid_argument for a missing side or if d_i is already
// GBRibbonPatch::kMaxDegree (the format's limit).
GBRibbonPatch gb_ribbon_elevate(const GBRibbonPatch& patch, int side);

// Ribbon `side` with one more layer, l_i -> l_i + 1: the cross-boundary degree m = 2 l_i - 1
// grows by two, the rows elevated by two in h,
//   C'_k = sum_{r=0..2} binom(2,r) binom(m,k-r) / binom(m+2,k) C_{k-r},   k = 0 .. l_i,
// which needs the row C_{l_i} a half ribbon does not have: it is continued linearly,
// C_{l_i} = 2 C_{l_i-1} - C_{l_i-2} (so a ribbon linear in h stays that ribbon). Rows 0 and 1
// give the same cross derivative, (m+2)(C'_1 - C'_0) = m (C_1 - C_0). Throws std::invalid_argument
// for a missing side or if l_i is already GBRibbonPatch::kMaxLayers (the format's limit).
GBRibbonPatch gb_ribbon_add_layer(const GBRibbonPatch& patch, int side);

// The same on one ribbon's rows (rows[k][j] = C_{j,k}, at least 2 rows of equal length).
std::vector<std::vector<Vec3>> ribbon_with_layer(const std::vector<std::vector<Vec3>>& rows);

}  // namespace pl
