// Golden images of a canonical bicubic saddle in each mode (golden.hpp compares them).
#include "golden.hpp"

#include <algorithm>

#include "core/curve/curvature_comb.hpp"
#include "render/frame.hpp"
#include "render/gpu_scene.hpp"
#include "render_test_util.hpp"

namespace pl {
namespace {

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
  r.width = 320 * panels;
  r.height = 240;
  r.settings = parse_display_mode(mode);
  std::vector<const SurfaceMesh*> meshes;
  for (const SurfaceMesh& m : scene.surfaces) meshes.push_back(&m);
  r.range = automatic_range(meshes, r.settings.curvature);
  for (int i = 0; i < panels; ++i) {
    FramePanel& p = r.panels.emplace_back();
    p.scene = &gpu;
    if (panels > 1) p.label.push_back('A');
  }
  r.camera = preset_camera(view, scene.bounds(), panel_aspect(r));
  return render_frame(renderer, r);
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
  test::compare_with_golden(c.name, render(saddle_scene(), c.mode, c.view, c.panels));
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
