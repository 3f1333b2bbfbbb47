// Shared by the ribbon-scheme tests: the reference faces and samples of tests/data/schemes
// (README there) and a few property helpers.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "core/patch/transfinite/ribbon_patch.hpp"
#include "gb_test_util.hpp"

namespace pl::test {

inline std::filesystem::path scheme_reference_dir() {
  return std::filesystem::path(PATCHLAB_TEST_DATA_DIR) / "schemes";
}

inline SceneCurve bezier_curve_of(std::vector<Vec3> points) {
  SceneCurve c;
  c.type = CurveType::Bezier;
  c.points = std::move(points);
  return c;
}

// faces/faceN.txt: "n N", then per side "side i", "P 3" + 4 points, "D m" + m + 1 points.
inline std::vector<RibbonSide> read_reference_face(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error("missing reference face " + file.string());
  std::vector<std::string> tokens;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream ls(line);
    for (std::string t; ls >> t;) tokens.push_back(t);
  }
  std::size_t k = 0;
  const auto next = [&] { return tokens.at(k++); };
  const auto points = [&](int count) {
    std::vector<Vec3> p(static_cast<std::size_t>(count));
    for (Vec3& q : p)
      for (int c = 0; c < 3; ++c) q[c] = std::stod(next());  // in order (argument order is not)
    return p;
  };
  if (next() != "n") throw std::runtime_error("bad face file " + file.string());
  const int n = std::stoi(next());
  std::vector<RibbonSide> sides;
  for (int i = 0; i < n; ++i) {
    next(), next();  // side i
    next();          // P
    const int dp = std::stoi(next());
    RibbonSide s;
    s.curve = bezier_curve_of(points(dp + 1));
    next();  // D
    const int dd = std::stoi(next());
    s.cross = bezier_curve_of(points(dd + 1));
    sides.push_back(std::move(s));
  }
  return sides;
}

// faces/faceN.txt of the reference folder.
inline std::vector<RibbonSide> reference_face(int n) {
  return read_reference_face(scheme_reference_dir() / "faces" /
                             ("face" + std::to_string(n) + ".txt"));
}

// The sample files have the layout of the GB reference samples ("u v x y z" after one comment
// line): the same reader. A missing file reads as no samples, which the tests' count check fails.
using SchemeSample = GBSample;
inline std::vector<SchemeSample> read_scheme_samples(const std::filesystem::path& file) {
  if (!std::filesystem::exists(file)) ADD_FAILURE() << "missing reference samples " << file;
  return read_gb_samples(file);
}

inline double points_diagonal(const std::vector<RibbonSide>& sides) {
  Vec3 lo(1e300), hi(-1e300);
  for (const RibbonSide& s : sides)
    for (const Vec3& p : s.curve.points) lo = glm::min(lo, p), hi = glm::max(hi, p);
  return glm::length(hi - lo);
}

}  // namespace pl::test
