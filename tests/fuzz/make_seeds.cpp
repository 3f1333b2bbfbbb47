// Writes generated seed inputs for the fuzz targets into DIR/scene and DIR/gbp: patch types and
// networks made by the library itself (so seeds follow the formats as they change), beside the
// scenes of assets/ that tests/fuzz/run.sh copies.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "core/io/gbp_io.hpp"
#include "core/io/scene_io.hpp"
#include "core/network/sample_networks.hpp"
#include "core/patch/catmull_clark_patch.hpp"
#include "core/patch/gb/default_net.hpp"
#include "core/patch/gb/gb_patch.hpp"

namespace {

void save(const std::filesystem::path& p, const std::string& text) {
  std::ofstream(p, std::ios::binary) << text;
}

pl::GBPatch wavy_gb(int n, int d) {
  std::vector<pl::Vec3> pts(pl::GBPatch::point_count(n, d));
  for (std::size_t k = 0; k < pts.size(); ++k)
    pts[k] = {std::cos(0.7 * k), std::sin(1.3 * k), 0.1 * std::sin(2.1 * k)};
  return pl::gb_default_net(pl::GBPatch(n, d, std::move(pts)), 1);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: patchlab_fuzz_seeds DIR\n");
    return 2;
  }
  const std::filesystem::path dir = argv[1];
  std::filesystem::create_directories(dir / "scene");
  std::filesystem::create_directories(dir / "gbp");
  int count = 0;
  for (int n = 3; n <= 7; ++n)
    for (int d = 1; d <= 5; d += 2) {
      const pl::GBPatch g = wavy_gb(n, d);
      save(dir / "gbp" / ("gb" + std::to_string(n) + "_" + std::to_string(d) + ".gbp"),
           pl::gbp_to_text(g));
      pl::Scene s;
      s.patches.push_back({"gb", std::make_shared<pl::GBPatch>(g)});
      save(dir / "scene" / ("gb" + std::to_string(n) + "_" + std::to_string(d) + ".json"),
           pl::scene_to_json(s));
      count += 2;
    }
  for (const auto scheme : {pl::FaceScheme::Auto, pl::FaceScheme::GB, pl::FaceScheme::Gregory}) {
    pl::Scene s;
    s.network = pl::cube_sphere_network(1, scheme);
    save(dir / "scene" / ("cube_sphere_" + std::to_string(int(scheme)) + ".json"),
         pl::scene_to_json(s));
    ++count;
  }
  {
    std::vector<pl::Vec3> v;
    for (int i = 0; i < 8; ++i) v.push_back({double(i & 1), double((i >> 1) & 1), double(i >> 2)});
    pl::Scene s;
    s.patches.push_back(
        {"cube",
         std::make_shared<pl::CatmullClarkPatch>(v, std::vector<std::vector<int>>{{0, 2, 3, 1},
                                                                                  {4, 5, 7, 6},
                                                                                  {0, 1, 5, 4},
                                                                                  {2, 6, 7, 3},
                                                                                  {0, 4, 6, 2},
                                                                                  {1, 3, 7, 5}})});
    save(dir / "scene" / "catmull_clark_cube.json", pl::scene_to_json(s));
    ++count;
  }
  std::printf("wrote %d seeds to %s\n", count, dir.c_str());
  return 0;
}
