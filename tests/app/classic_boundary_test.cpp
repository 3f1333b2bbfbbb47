// `patchlab analyze --json` and `export` on every classic sample scene: each side of every
// surface lies on its defining boundary curve (multi-span B-spline/NURBS sides, multi-cell Coons
// networks, the pair-join and gap-fill composites, Catmull-Clark faces through OpenSubdiv's limit
// stencils), so max_boundary_deviation is rounding noise relative to the scene size.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cli_test_util.hpp"
#include "core/domain/tessellation_cache.hpp"
#include "core/eval/scene_surfaces.hpp"
#include "core/io/scene_io.hpp"

namespace pl::test {
namespace {

std::vector<std::filesystem::path> classic_assets() {
  std::vector<std::filesystem::path> r;
  for (const auto& e : std::filesystem::directory_iterator(
           std::filesystem::path(PATCHLAB_SOURCE_DIR) / "assets/classic"))
    if (e.path().extension() == ".json") r.push_back(e.path());
  std::sort(r.begin(), r.end());
  return r;
}

// The diagonal of the evaluated samples' bounding box: the scale of the scene.
double scene_size(const std::filesystem::path& file) {
  TessellationCache cache;
  const SceneSurfaces ss = evaluate_scene(read_scene(file), 8, std::nullopt, cache, file.string());
  Vec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  for (const auto& s : ss.surfaces)
    for (const auto& j : s.evaluator->jets()) lo = glm::min(lo, j.p), hi = glm::max(hi, j.p);
  return glm::length(hi - lo);
}

TEST(ClassicBoundary, AnalyzeReportsExactBoundariesOnEverySampleScene) {
  const auto files = classic_assets();
  ASSERT_GE(files.size(), 8u);
  for (const auto& file : files) {
    const double size = scene_size(file);
    ASSERT_GT(size, 0) << file;
    // Densities that put samples on span/cell/piece breaks (12) and between them (17).
    for (const char* density : {"12", "17"}) {
      const CliResult r = cli({"analyze", file.string(), "--json", "--density", density});
      ASSERT_EQ(r.code, kExitOk) << file << ": " << r.err;
      const auto j = nlohmann::json::parse(r.out);
      ASSERT_FALSE(j["patches"].empty()) << file;
      double worst = 0;
      for (const auto& p : j["patches"]) {
        EXPECT_EQ(p["nonfinite_samples"], 0) << file << " " << p["name"];
        const double d = p["max_boundary_deviation"].get<double>();
        worst = std::max(worst, d);
        EXPECT_LT(d, 1e-12 * size) << file << " " << p["name"] << " density " << density;
      }
      std::printf("figure classic_%s_density_%s_boundary_deviation_relative %.3e\n",
                  file.stem().string().c_str(), density, worst / size);
    }
  }
}

TEST(ClassicBoundary, ExportWritesEverySampleSceneWithFiniteVertices) {
  for (const auto& file : classic_assets()) {
    TempDir dir;
    const auto obj = dir / "out.obj";
    const CliResult r = cli({"export", file.string(), "-o", obj.string(), "--density", "8"});
    ASSERT_EQ(r.code, kExitOk) << file << ": " << r.err;
    std::istringstream in(slurp(obj));
    std::string line;
    std::size_t v = 0;
    while (std::getline(in, line)) {
      if (line.rfind("v ", 0) != 0 && line.rfind("vn ", 0) != 0) continue;
      std::istringstream ls(line.substr(line.find(' ') + 1));
      double x, y, z;
      ASSERT_TRUE(ls >> x >> y >> z) << file << ": " << line;
      EXPECT_TRUE(std::isfinite(x) && std::isfinite(y) && std::isfinite(z)) << file << ": " << line;
      v += line[1] == ' ';
    }
    EXPECT_GT(v, 0u) << file;
  }
}

}  // namespace
}  // namespace pl::test
