// The midpoint Coons (MC) patch: Salvi, Varady et al., "Computationally efficient transfinite
// patches with fullness control", arXiv:2002.11212. The generalized Coons combination of side
// interpolants and corner patches weighted by the deficient corner blend, the deficiency given
// to the central control point:
// S = sum_i [(w_i + w_{i-1}) I_i(s_i, d_i) - w_i Q_i(1 - s_i, s_{i+1})] + (1 - sum_i w_i) C,
// with the constrained barycentric parameters (d_i behaves like a distance near every side).
#include "core/patch/transfinite/blends.hpp"
#include "core/patch/transfinite/ribbon_scheme.hpp"
#include "core/patch/transfinite/vec_jet.hpp"

namespace pl::transfinite {

DeficientSurface midpoint_coons_surface(const SchemeInput& in, Vec2 x) {
  const SideParameters p = in.domain.constrained_barycentric(x);
  const std::vector<Jet> w = deficient_corner_blend(p.s, p.d);
  const RibbonSet& r = in.ribbons;
  DeficientSurface out;
  out.deficiency = Jet(1.0);
  for (int i = 0; i < r.size(); ++i) {
    out.s0 += (w[i] + w[r.wrap(i - 1)]) * r.side_interpolant(i, p.s[i], p.d[i]);
    out.s0 -= w[i] * r.corner_correction(i, 1.0 - p.s[i], p.s[r.wrap(i + 1)]);
    out.deficiency -= w[i];
  }
  return out;
}

}  // namespace pl::transfinite
