// Fairness integrals of one evaluated surface, over its tessellation:
//   area                 ∫ dA
//   bending energy       ∫ (k1² + k2²) dA  (the thin-plate energy; = ∫ 4H² − 2K dA)
//   mean-curvature       ∫ |∇H|² dA        (∇H the surface gradient of H: zero on spheres,
//   gradient energy                          cylinders and planes, the fairness of Moreton and
//                                            Séquin's minimum-variation surfaces)
// Quadrature: the flat triangles of the tessellation, each vertex carrying the exact sample
// values (curvatures from the patch derivatives). Area and bending energy: Σ_T A_T · (f_a + f_b +
// f_c) / 3, the vertex rule on every triangle (second order in the sample spacing h: the chords
// and the linear interpolation both err by O(h²)). Mean-curvature gradient: H is interpolated
// linearly on each flat triangle and its gradient taken there (constant per triangle:
// ∇H_T = Σ_i H_i (n_T × e_i) / (2 A_T), e_i the edge opposite vertex i), so no third derivative
// of the patch is needed; Σ_T A_T |∇H_T|², first order in h in general. Triangles of zero area
// (a collapsed corner) contribute nothing. tests/core/surface_energy_test.cpp checks all three
// against closed forms on a sphere, a cylinder and a paraboloid.
#pragma once

#include "core/eval/patch_evaluator.hpp"

namespace pl {

struct SurfaceIntegrals {
  double area = 0;
  double bending_energy = 0;                  // ∫ (k1² + k2²) dA
  double mean_curvature_gradient_energy = 0;  // ∫ |∇H|² dA
};

SurfaceIntegrals surface_integrals(const PatchEvaluator& evaluator);

}  // namespace pl
