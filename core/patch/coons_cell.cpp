#include "core/patch/coons_cell.hpp"

#include <cassert>

namespace pl {

namespace {
struct Hermite {  // a0, a1, b0, b1 and their first derivatives as jets of one variable
  Jet a[2], b[2], da[2], db[2];
  explicit Hermite(const Jet& t) {
    const Jet t2 = t * t, t3 = t2 * t;
    a[0] = 1.0 - 3.0 * t2 + 2.0 * t3;
    a[1] = 3.0 * t2 - 2.0 * t3;
    b[0] = t - 2.0 * t2 + t3;
    b[1] = t3 - t2;
    da[0] = 6.0 * t2 - 6.0 * t;
    da[1] = 6.0 * t - 6.0 * t2;
    db[0] = 1.0 - 4.0 * t + 3.0 * t2;
    db[1] = 3.0 * t2 - 2.0 * t;
  }
};
}  // namespace

void coons_cell_basis(Vec2 uv, const CellLengths& L, std::span<Jet> out) {
  assert(out.size() == 16);
  for (Jet& j : out) j = Jet(0.0);
  const Jet u = Jet::u(uv.x), v = Jet::v(uv.y);
  const Hermite hu(u), hv(v);
  const double S[2] = {L.S0, L.S1}, T[2] = {L.T0, L.T1};
  const Jet Sv = (1.0 - v) * L.S0 + v * L.S1, Tu = (1.0 - u) * L.T0 + u * L.T1;
  const auto idx = [](int i, int j, int q) { return (i * 2 + j) * 4 + q; };
  for (int i = 0; i < 2; ++i) {
    const Jet lambda = (L.T1 - L.T0) / T[i] * (hv.b[0] + hv.b[1]);  // on boundary u = i
    for (int j = 0; j < 2; ++j) {
      const Jet kappa = (L.S1 - L.S0) / S[j] * (hu.b[0] + hu.b[1]);  // on boundary v = j
      Jet* r = &out[idx(i, j, 0)];  // r, r_s, r_t, r_st of corner (i, j)
      // u-direction: a_i(u) R_i(v) + b_i(u) [S(v) Rs_i(v) + lambda_i(v) R_i'(v)]
      r[0] += hu.a[i] * hv.a[j] + hu.b[i] * lambda * hv.da[j];
      r[2] += T[i] * (hu.a[i] * hv.b[j] + hu.b[i] * lambda * hv.db[j]);
      r[1] += hu.b[i] * Sv * hv.a[j];
      r[3] += T[i] * hu.b[i] * Sv * hv.b[j];
      // v-direction: a_j(v) C_j(u) + b_j(v) [T(u) Ct_j(u) + kappa_j(u) C_j'(u)]
      r[0] += hv.a[j] * hu.a[i] + hv.b[j] * kappa * hu.da[i];
      r[1] += S[j] * (hv.a[j] * hu.b[i] + hv.b[j] * kappa * hu.db[i]);
      r[2] += hv.b[j] * Tu * hu.a[i];
      r[3] += S[j] * hv.b[j] * Tu * hu.b[i];
      // minus the tensor-product part counted twice: corner r, r_v, r_u and the twist.
      const Jet aa = hu.a[i] * hv.a[j], ab = hu.a[i] * hv.b[j], ba = hu.b[i] * hv.a[j],
                bb = hu.b[i] * hv.b[j];
      r[0] -= aa;
      r[2] -= T[i] * ab;
      r[1] -= S[j] * ba;
      r[3] -= S[j] * T[i] * bb;
      r[1] -= (L.S1 - L.S0) * bb;
      r[2] -= (L.T1 - L.T0) * bb;
    }
  }
}

}  // namespace pl
