#include "core/patch/gb/ribbon.hpp"

#include <algorithm>

namespace pl {

RibbonRows::RibbonRows(int sides, int degree, int layers, const std::vector<Mu>& mu)
    : n_(sides), d_(degree), l_(layers) {
  rows_.assign(static_cast<std::size_t>(n_) * kMuGroups * l_ * (d_ + 1), Vec3(0));
  span_.assign(kMuGroups * l_, Span{d_ + 1, -1});
  for (int g = 0; g < kMuGroups; ++g)
    for (int k = 0; k < l_; ++k)
      for (int j = 0; j <= d_; ++j) {
        if (mu_group_factor(mu[k * (d_ + 1) + j], g) == 0) continue;
        Span& sp = span_[g * l_ + k];
        sp.first = std::min(sp.first, j), sp.last = std::max(sp.last, j);
      }
}

void RibbonRows::set(int i, int j, int k, Mu m, const Vec3& relative) {
  for (int g = 0; g < kMuGroups; ++g) {
    const double c = mu_group_factor(m, g);
    if (c != 0) rows_[((i * kMuGroups + g) * l_ + k) * (d_ + 1) + j] = c * relative;
  }
}

}  // namespace pl
