// The side-based (SB) patch, a variation of Kato's patch: Salvi, Varady, Rockwood,
// "Ribbon-based transfinite surfaces", Computer Aided Geometric Design 31 (2014),
// doi:10.1016/j.cagd.2014.06.006. S = sum_i w_i I_i(s_i, d_i): each side interpolant weighted by
// the side blend (w_i proportional to d_i^-2), with the parallel parameterization (d_i a scaled
// distance from side i). It uses no corner data, hence no twists.
#include "core/patch/transfinite/blends.hpp"
#include "core/patch/transfinite/ribbon_scheme.hpp"
#include "core/patch/transfinite/vec_jet.hpp"

namespace pl::transfinite {

SurfaceJet side_based_surface(const SchemeInput& in, Vec2 x) {
  const SideParameters p = in.domain.parallel(x);
  const std::vector<Jet> w = side_blend(p.d);
  SurfaceJet s;
  for (int i = 0; i < in.ribbons.size(); ++i)
    s += w[i] * in.ribbons.side_interpolant(i, p.s[i], p.d[i]);
  return s;
}

}  // namespace pl::transfinite
