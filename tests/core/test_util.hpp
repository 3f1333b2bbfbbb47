// Helpers shared by the core tests.
#pragma once

#include <cmath>
#include <random>

#include "core/math/vec.hpp"
#include "core/patch/patch.hpp"

namespace pl::test {

inline double max_abs(const Vec3& v) {
  return std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
}

// Central finite differences of S at x with step h: the independent check of exact derivatives.
struct FiniteDifferences {
  Vec3 su, sv, suu, suv, svv;
};
inline FiniteDifferences finite_differences(const Patch& p, Vec2 x, double h) {
  const auto S = [&](double du, double dv) { return p.evaluate({x.x + du, x.y + dv}).p; };
  FiniteDifferences d;
  d.su = (S(h, 0) - S(-h, 0)) / (2 * h);
  d.sv = (S(0, h) - S(0, -h)) / (2 * h);
  d.suu = (S(h, 0) - 2.0 * S(0, 0) + S(-h, 0)) / (h * h);
  d.svv = (S(0, h) - 2.0 * S(0, 0) + S(0, -h)) / (h * h);
  d.suv = (S(h, h) - S(h, -h) - S(-h, h) + S(-h, -h)) / (4 * h * h);
  return d;
}

inline std::vector<Vec3> random_points(std::size_t n, unsigned seed, double scale = 1.0) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> d(-scale, scale);
  std::vector<Vec3> r(n);
  for (auto& p : r) p = {d(rng), d(rng), d(rng)};
  return r;
}

}  // namespace pl::test
