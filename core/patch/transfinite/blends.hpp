// The blending functions of the ribbon-based schemes (Salvi, Varady, Rockwood, "Ribbon-based
// transfinite surfaces", CAGD 31 (2014); the deficient corner blend: Salvi et al.,
// "Computationally efficient transfinite patches with fullness control", arXiv:2002.11212).
// The singular forms of the papers (weights proportional to d^-2) are written as products of the
// other sides' squared distances over their sum, the same functions without the poles: they are
// exact Jets on the sides of the domain, and only the domain vertices (where the schemes take
// their limits) are left singular.
#pragma once

#include <vector>

#include "core/math/jet.hpp"

namespace pl::transfinite {

// Side blend: w_i = d_i^-2 / sum_j d_j^-2 (1 on side i, 0 on the other sides).
std::vector<Jet> side_blend(const std::vector<Jet>& d);
// Corner blend: w_i = (d_i d_{i+1})^-2 / sum_j (d_j d_{j+1})^-2, corner i between sides i and
// i+1. Finite at the domain vertices too (w_i = 1 at vertex i).
std::vector<Jet> corner_blend(const std::vector<Jet>& d);
// Deficient corner blend: w_i = [d_{i+1} H(1 - s_i) H(d_i) + d_i H(s_{i+1}) H(d_{i+1})] /
// (d_i + d_{i+1}); sum w_i < 1 inside, the rest goes to the central point.
std::vector<Jet> deficient_corner_blend(const std::vector<Jet>& s, const std::vector<Jet>& d);

}  // namespace pl::transfinite
