// The composite ribbon (CR) patch: Salvi, Varady, Rockwood, "Ribbon-based transfinite
// surfaces", CAGD 31 (2014). Each side gets a composite ribbon CR_i, a Coons-like combination
// of its own side interpolant and its two neighbours' (minus the two corner patches), blended by
// Hermite functions of (s_i, d_i); S = 1/2 sum_i (w_i + w_{i-1}) CR_i(s_i, d_i) with the corner
// blend and Wachspress-based parameters.
#include "core/patch/transfinite/blends.hpp"
#include "core/patch/transfinite/ribbon_scheme.hpp"
#include "core/patch/transfinite/vec_jet.hpp"

namespace pl::transfinite {

namespace {

// CR_i(s, d) = I_i(s, d) H(d) + I_{i-1}(1 - d, s) H(s) + I_{i+1}(d, 1 - s) (1 - H(s))
//            - Q_{i-1}(d, s) H(s) H(d) - Q_i(1 - s, d) (1 - H(s)) H(d).
SurfaceJet composite_ribbon(const RibbonSet& r, int i, const Jet& s, const Jet& d) {
  const Jet hs = hermite_blend(s), hd = hermite_blend(d);
  const Jet one_s = 1.0 - s, one_d = 1.0 - d, one_hs = 1.0 - hs;
  SurfaceJet c = hd * r.side_interpolant(i, s, d);
  c += hs * r.side_interpolant(i - 1, one_d, s);
  c += one_hs * r.side_interpolant(i + 1, d, one_s);
  c -= (hs * hd) * r.corner_correction(i - 1, d, s);
  c -= (one_hs * hd) * r.corner_correction(i, one_s, d);
  return c;
}

}  // namespace

SurfaceJet composite_ribbon_surface(const SchemeInput& in, Vec2 x) {
  const SideParameters p = in.domain.barycentric(x);
  const std::vector<Jet> w = corner_blend(p.d);
  const RibbonSet& r = in.ribbons;
  SurfaceJet s;
  for (int i = 0; i < r.size(); ++i)
    s += (0.5 * (w[i] + w[r.wrap(i - 1)])) * composite_ribbon(r, i, p.s[i], p.d[i]);
  return s;
}

}  // namespace pl::transfinite
