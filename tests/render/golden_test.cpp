// Golden images: small renders of canonical scenes in each mode, compared pixel by pixel with
// tests/data/golden/NAME.png. Regenerate after an intended visual change with
//   PATCHLAB_UPDATE_GOLDENS=1 build/tests/patchlab_render_tests --gtest_filter='Golden*'
// and look at the new PNGs before committing them.
#include <stb_image.h>  // implementation compiled into Debian's libstb

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "core/curve/curvature_comb.hpp"
#include "render/frame.hpp"
#include "render/gpu_scene.hpp"
#include "render_test_util.hpp"

namespace pl {
namespace {

// Per channel, in 8-bit levels: absorbs rasteriser rounding differences between Mesa versions
// on smooth shading and colour ramps.
constexpr int kChannelTolerance = 8;
// Pixels allowed beyond that: antialiased silhouettes and line edges may move by a sample.
constexpr double kOutlierFraction = 0.003;

const std::filesystem::path kGoldenDir =
    std::filesystem::path(PATCHLAB_SOURCE_DIR) / "tests" / "data" / "golden";

DrawScene saddle_scene() {
  DrawScene d;
  const std::vector<Vec3> points = test::saddle_points();
  d.surfaces.push_back(test::bezier_mesh(3, 3, points, 16, "saddle"));
  // The Bézier grid as control net, kinds as the core defines them for a bicubic.
  BezierPatch patch(3, 3, points);
  for (std::size_t k = 0; k < patch.size(); ++k) {
    d.net.points.push_back(patch.control_point(k));
    d.net.kinds.push_back(patch.kind(k));
  }
  for (uint32_t i = 0; i < 4; ++i)
    for (uint32_t j = 0; j < 4; ++j) {
      if (i < 3) d.net.segments.push_back({i * 4 + j, (i + 1) * 4 + j});
      if (j < 3) d.net.segments.push_back({i * 4 + j, i * 4 + j + 1});
    }
  for (const BezierCurve& c : patch.boundary_curves()) {
    Polyline l;
    for (int i = 0; i <= 32; ++i) l.push_back(c.point(i / 32.0));
    d.borders.push_back(l);
    d.border_combs.push_back(curvature_comb(c, 12));
  }
  return d;
}

Image render(const DrawScene& scene, const std::string& mode, ViewPreset view, int panels) {
  SceneRenderer renderer;
  GpuScene gpu(scene);
  FrameRequest r;
  r.width = 160 * panels;
  r.height = 120;
  r.settings = parse_display_mode(mode);
  std::vector<const SurfaceMesh*> meshes;
  for (const SurfaceMesh& m : scene.surfaces) meshes.push_back(&m);
  r.range = automatic_range(meshes, r.settings.curvature);
  r.camera = preset_camera(view, scene.bounds(),
                           panel_aspect(r.width, r.height, panels, r.settings, r.range));
  for (int i = 0; i < panels; ++i) r.panels.push_back({&gpu, panels > 1 ? "A" : ""});
  return render_frame(renderer, r);
}

void compare_with_golden(const std::string& name, const Image& image) {
  const auto path = kGoldenDir / (name + ".png");
  const char* update = std::getenv("PATCHLAB_UPDATE_GOLDENS");
  if (update && std::string(update) == "1") {
    std::filesystem::create_directories(kGoldenDir);
    std::ofstream(path, std::ios::binary) << encode_png(image);
    std::cout << "updated " << path << "\n";
    return;
  }
  int w = 0, h = 0, channels = 0;
  stbi_uc* golden = stbi_load(path.string().c_str(), &w, &h, &channels, 4);
  ASSERT_NE(golden, nullptr) << "missing golden " << path
                             << " (create it with PATCHLAB_UPDATE_GOLDENS=1)";
  ASSERT_EQ(w, image.width);
  ASSERT_EQ(h, image.height);
  int outliers = 0, worst = 0;
  for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
    int d = 0;
    for (int k = 0; k < 4; ++k) d = std::max(d, std::abs(int(golden[i + k]) - image.rgba[i + k]));
    worst = std::max(worst, d);
    if (d > kChannelTolerance) ++outliers;
  }
  stbi_image_free(golden);
  const int allowed = static_cast<int>(kOutlierFraction * w * h);
  if (outliers > allowed) {
    const auto actual = std::filesystem::temp_directory_path() / (name + ".actual.png");
    std::ofstream(actual, std::ios::binary) << encode_png(image);
    ADD_FAILURE() << name << ": " << outliers << " pixels differ by more than " << kChannelTolerance
                  << " levels (allowed " << allowed << ", worst " << worst
                  << "); this render is in " << actual;
  }
}

struct GoldenCase {
  const char* name;
  const char* mode;
  ViewPreset view;
  int panels;
};

class Golden : public ::testing::TestWithParam<GoldenCase> {};

TEST_P(Golden, MatchesStoredImage) {
  PATCHLAB_REQUIRE_GL();
  const GoldenCase& c = GetParam();
  compare_with_golden(c.name, render(saddle_scene(), c.mode, c.view, c.panels));
}

INSTANTIATE_TEST_SUITE_P(
    Saddle, Golden,
    ::testing::Values(GoldenCase{"saddle-shaded", "shaded+borders", ViewPreset::Iso, 1},
                      GoldenCase{"saddle-isophotes", "isophotes", ViewPreset::Iso, 1},
                      GoldenCase{"saddle-zebra", "zebra", ViewPreset::Front, 1},
                      GoldenCase{"saddle-mean-net", "mean+control-net", ViewPreset::Iso, 1},
                      GoldenCase{"saddle-gaussian-iso", "gaussian+isophotes", ViewPreset::Top, 1},
                      GoldenCase{"saddle-compare-kmax", "kmax", ViewPreset::Iso, 2},
                      GoldenCase{"saddle-combs", "shaded+borders+combs", ViewPreset::Iso, 1}),
    [](const auto& info) {
      std::string n = info.param.name;
      std::replace(n.begin(), n.end(), '-', '_');
      return n;
    });

}  // namespace
}  // namespace pl
