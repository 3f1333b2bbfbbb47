// The corner-based (CB) patch, a variation of the Charrot-Gregory patch (Charrot, Gregory,
// "A pentagonal surface patch for computer aided geometric design", CAGD 1 (1984)), as
// formulated by Salvi, Varady, Rockwood, "Ribbon-based transfinite surfaces", CAGD 31 (2014).
// S = sum_i w_i K_i: the corner interpolants K_i (two side interpolants minus their common
// corner patch Q_i) weighted by the corner blend, with the bilinear parameterization; the d_i
// enter the blend only.
#include "core/patch/transfinite/blends.hpp"
#include "core/patch/transfinite/ribbon_scheme.hpp"
#include "core/patch/transfinite/vec_jet.hpp"

namespace pl::transfinite {

SurfaceJet corner_based_surface(const SchemeInput& in, Vec2 x) {
  const SideParameters p = in.domain.bilinear(x);
  const std::vector<Jet> w = corner_blend(p.d);
  SurfaceJet s;
  for (int i = 0; i < in.ribbons.size(); ++i) s += w[i] * in.ribbons.corner_interpolant(i, p.s);
  return s;
}

}  // namespace pl::transfinite
