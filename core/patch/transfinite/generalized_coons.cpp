// The generalized Coons (GC) patch: Salvi, Varady, Rockwood, "Ribbon-based transfinite
// surfaces", CAGD 31 (2014). The Boolean-sum form of a Coons patch over n sides:
// S = sum_i [(w_i + w_{i-1}) I_i(s_i, d_i) - w_i Q_i(1 - s_i, s_{i+1})], each side interpolant
// weighted by the corner blends of its two corners, minus each corner patch once; the
// interconnected parameterization (d_i built from the neighbours' s).
#include "core/patch/transfinite/blends.hpp"
#include "core/patch/transfinite/ribbon_scheme.hpp"
#include "core/patch/transfinite/vec_jet.hpp"

namespace pl::transfinite {

SurfaceJet generalized_coons_surface(const SchemeInput& in, Vec2 x) {
  const SideParameters p = in.domain.interconnected(x);
  const std::vector<Jet> w = corner_blend(p.d);
  const RibbonSet& r = in.ribbons;
  const int n = r.size();
  SurfaceJet s;
  for (int i = 0; i < n; ++i) {
    s += (w[i] + w[r.wrap(i - 1)]) * r.side_interpolant(i, p.s[i], p.d[i]);
    s -= w[i] * r.corner_correction(i, 1.0 - p.s[i], p.s[r.wrap(i + 1)]);
  }
  return s;
}

}  // namespace pl::transfinite
