// Independent reference computations for the classic-type tests.
#pragma once

#include <glm/vec4.hpp>
#include <vector>

#include "core/math/vec.hpp"
#include "core/patch/patch.hpp"
#include "test_util.hpp"

namespace pl::test {

// de Boor's triangle on homogeneous points (independent of the basis-function recursion).
inline glm::dvec4 de_boor(int p, const std::vector<double>& U, std::vector<glm::dvec4> P,
                          double t) {
  int k = p;
  while (k + 1 < static_cast<int>(P.size()) && U[k + 1] <= t) ++k;
  std::vector<glm::dvec4> d(P.begin() + (k - p), P.begin() + k + 1);
  for (int r = 1; r <= p; ++r)
    for (int j = p; j >= r; --j) {
      const int i = j + k - p;
      const double a = (t - U[i]) / (U[i + p - r + 1] - U[i]);
      d[j] = (1 - a) * d[j - 1] + a * d[j];
    }
  return d[p];
}

// Tensor-product de Boor: each u-row... each column j evaluated in u, then the results in v.
inline glm::dvec4 de_boor_surface(int p, int q, const std::vector<double>& U,
                                  const std::vector<double>& V, std::size_t nu, std::size_t nv,
                                  const std::vector<glm::dvec4>& P, double u, double v) {
  std::vector<glm::dvec4> col(nv);
  for (std::size_t j = 0; j < nv; ++j) {
    std::vector<glm::dvec4> row(nu);
    for (std::size_t i = 0; i < nu; ++i) row[i] = P[i * nv + j];
    col[j] = de_boor(p, U, row, u);
  }
  return de_boor(q, V, col, v);
}

// Largest difference between exact derivatives and central differences at x, relative to the
// derivative's size.
inline double fd_mismatch(const Patch& p, Vec2 x, double h = 1e-5) {
  const SurfaceJet s = p.evaluate(x);
  const FiniteDifferences d = finite_differences(p, x, h);
  const double scale1 = 1 + max_abs(s.su) + max_abs(s.sv);
  const double scale2 = 1 + max_abs(s.suu) + max_abs(s.suv) + max_abs(s.svv);
  return std::max({max_abs(s.su - d.su) / scale1, max_abs(s.sv - d.sv) / scale1,
                   1e-3 * max_abs(s.suu - d.suu) / scale2, 1e-3 * max_abs(s.suv - d.suv) / scale2,
                   1e-3 * max_abs(s.svv - d.svv) / scale2});
}

// The default basis-sum evaluation and every influence column against evaluate().
inline double interface_mismatch(const Patch& p, const std::vector<Vec2>& xs) {
  double worst = 0;
  std::vector<Jet> phi(p.size());
  for (const Vec2& x : xs) {
    p.basis(x, phi);
    const SurfaceJet a = combine(p.control_points(), phi), b = p.evaluate(x);
    worst = std::max({worst, max_abs(a.p - b.p), max_abs(a.su - b.su), max_abs(a.sv - b.sv),
                      max_abs(a.suu - b.suu), max_abs(a.suv - b.suv), max_abs(a.svv - b.svv)});
  }
  std::vector<Jet> col(xs.size());
  for (std::size_t k = 0; k < p.size(); ++k) {
    p.influence(k, xs, col);
    for (std::size_t s = 0; s < xs.size(); ++s) {
      p.basis(xs[s], phi);
      const Jet d = col[s] - phi[k];
      worst = std::max({worst, std::fabs(d.f), std::fabs(d.fu), std::fabs(d.fv), std::fabs(d.fuu),
                        std::fabs(d.fuv), std::fabs(d.fvv)});
    }
  }
  return worst;
}

inline std::vector<Vec2> random_domain_points(std::size_t n, unsigned seed, double lo = 0,
                                              double hi = 1) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> d(lo, hi);
  std::vector<Vec2> r(n);
  for (auto& x : r) x = {d(rng), d(rng)};
  return r;
}

}  // namespace pl::test
