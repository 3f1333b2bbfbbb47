// Helpers of the GB patch tests: the reference models of tests/data/gb and random GB nets.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "core/io/gbp_io.hpp"
#include "core/patch/gb/gb_patch.hpp"

namespace pl::test {

inline std::filesystem::path gb_reference_dir() {
  return std::filesystem::path(PATCHLAB_TEST_DATA_DIR) / "gb";
}

inline const std::vector<std::string>& gb_reference_models() {
  static const std::vector<std::string> m{"cagd86", "tp4-d3",   "tp4-d4",   "tp4-d5",
                                          "tp4-d6", "dome3-d3", "dome6-d4", "dome7-d3"};
  return m;
}

struct GBSample {
  Vec2 x;
  Vec3 p;
};

// The "u v x y z" lines of NAME.samples.txt (the first line is a comment).
inline std::vector<GBSample> read_gb_samples(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  std::vector<GBSample> out;
  while (std::getline(in, line)) {
    std::istringstream s(line);
    GBSample g;
    if (s >> g.x.x >> g.x.y >> g.p.x >> g.p.y >> g.p.z) out.push_back(g);
  }
  return out;
}

inline double bbox_diagonal(const std::vector<Vec3>& points) {
  Vec3 lo = points[0], hi = points[0];
  for (const Vec3& p : points) lo = glm::min(lo, p), hi = glm::max(hi, p);
  return glm::length(hi - lo);
}

// A smooth random-ish net: boundary on a wobbly circle, inner layers pulled in and raised.
inline GBPatch random_gb(int n, int d, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> r(-0.3, 0.3);
  std::vector<Vec3> p(GBPatch::point_count(n, d));
  p[0] = {r(rng), r(rng), 2 + r(rng)};
  // Place every grid position by its position in the domain, then perturb.
  GBPatch shape(n, d, p);
  const auto& dom = shape.polygon();
  for (int k = 0; k < shape.layers(); ++k)
    for (int i = 0; i < n; ++i)
      for (int j = k; j <= d - 1 - k; ++j) {
        const Vec2 a = dom.vertex(i - 1), b = dom.vertex(i);
        const Vec2 on = a + (double(j) / d) * (b - a);
        const Vec2 q = on * (1.0 - 0.8 * double(k) / d);
        p[shape.index(i, j, k)] = {4 * q.x + r(rng), 4 * q.y + r(rng), 1.5 * k + r(rng)};
      }
  return GBPatch(n, d, std::move(p));
}

// The reference data is part of the repository: a test that needs it fails without it.
#define PATCHLAB_REQUIRE_GB_REFERENCE()                                      \
  ASSERT_TRUE(std::filesystem::is_directory(::pl::test::gb_reference_dir())) \
      << "GB reference folder " << ::pl::test::gb_reference_dir() << " is missing"

}  // namespace pl::test
