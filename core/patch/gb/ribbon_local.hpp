// The local parameters of every side of a gb-ribbons patch at one sample (T = double) or a block
// of samples (T a lane type, one sample per lane): the mean value coordinates lambda, the
// distance parameters h, and the corner weights alpha of the squared variant (blend.hpp:
// w = h^2). Both forms run the same operations, so a lane holds the scalar numbers bit for bit.
#pragma once

#include "core/param/mean_value.hpp"
#include "core/patch/gb/blend.hpp"

namespace pl {

template <class T>
struct RibbonLocalOf {
  using J = JetOf<T>;
  Scratch<J, MeanValueParameters::kMaxSides> lam, h, alpha;

  PATCHLAB_LANES_INLINE RibbonLocalOf(const MeanValueParameters& params, const T& u, const T& v) {
    const int n = params.sides();
    if constexpr (std::is_same_v<T, double>)
      params.evaluate({u, v}, std::span(lam.data(), n), {}, std::span(h.data(), n));
    else
      params.evaluate_lanes(u, v, lam.data(), h.data());
    Scratch<J, MeanValueParameters::kMaxSides> h2;
    for (int i = 0; i < n; ++i) h2[i] = product(h[i], h[i]);
    corner_alphas(n, h2.data(), alpha.data());
  }
};

}  // namespace pl
