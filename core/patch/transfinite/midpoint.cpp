// The midpoint (MP) patch: Salvi, Varady et al., "Computationally efficient transfinite patches
// with fullness control", arXiv:2002.11212. The corner interpolants K_i of the corner-based patch
// weighted by the deficient corner blend (Hermite functions of s and d, summing to less than 1
// inside), the deficiency 1 - sum w_i given to a central control point C:
// S = sum_i w_i K_i + (1 - sum_i w_i) C, with Wachspress-based parameters. C is chosen so that
// the surface passes through the patch's midpoint at the domain centre (the fullness control).
#include "core/patch/transfinite/blends.hpp"
#include "core/patch/transfinite/ribbon_scheme.hpp"
#include "core/patch/transfinite/vec_jet.hpp"

namespace pl::transfinite {

DeficientSurface midpoint_surface(const SchemeInput& in, Vec2 x) {
  const SideParameters p = in.domain.barycentric(x);
  const std::vector<Jet> w = deficient_corner_blend(p.s, p.d);
  DeficientSurface out;
  out.deficiency = Jet(1.0);
  for (int i = 0; i < in.ribbons.size(); ++i) {
    out.s0 += w[i] * in.ribbons.corner_interpolant(i, p.s);
    out.deficiency -= w[i];
  }
  return out;
}

}  // namespace pl::transfinite
