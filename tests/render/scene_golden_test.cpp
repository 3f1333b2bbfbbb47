// Golden images of whole scenes as a designer sees them: the point kinds of the default scene,
// the control nets of a GB and a B-spline patch, the Hermite patch's derivative arrows, the
// comparison coloured by the distance between the two fillings with its legend, and the legend
// of a 4096 x 4096 picture (golden.hpp compares them; look at them after regenerating).
#include <algorithm>

#include "core/network/network_filling.hpp"
#include "golden.hpp"
#include "render/default_view.hpp"
#include "render/frame.hpp"
#include "render/gpu_scene.hpp"
#include "render_test_util.hpp"

// The comparison's distance field (the editor's, GUI-free).
#include "core/analysis/surface_distance.hpp"

namespace pl {
namespace {

// A scene's control net in the default view at 640 x 480, as `patchlab render FILE --mode
// shaded+control-net` draws it.
struct NetCase {
  const char* golden;
  const char* asset;
  std::optional<FaceScheme> scheme;
};

class SceneGolden : public ::testing::TestWithParam<NetCase> {};

TEST_P(SceneGolden, ControlNetInTheDefaultView) {
  PATCHLAB_REQUIRE_GL();
  const NetCase& c = GetParam();
  const DrawScene d = test::file_draw_scene(test::asset(c.asset), c.scheme);
  SceneRenderer renderer;
  const GpuScene gpu(d);
  const DisplaySettings net = parse_display_mode("shaded+control-net");
  test::compare_with_golden(c.golden,
                            render_frame(renderer, test::one_panel(gpu, d, net, 640, 480)));
}

INSTANTIATE_TEST_SUITE_P(
    Nets, SceneGolden,
    ::testing::Values(
        // The network's points editable, the Gregory twins and GB ribbon rows of its faces
        // derived.
        NetCase{"default-point-kinds", "default.json", {}},
        // GB fillings of network faces: ribbon rows and spokes derived from the network.
        NetCase{"gb-faces-control-net", "gb-hole-filling.json", FaceScheme::GB},
        NetCase{"bspline-control-net", "classic/bspline.json", {}},
        // Tangents and twists as arrows from the corners.
        NetCase{"hermite-arrows", "classic/hermite.json", {}}),
    [](const auto& info) {
      std::string n = info.param.golden;
      std::replace(n.begin(), n.end(), '-', '_');
      return n;
    });

// The GB filling's mean curvature replaced by its signed distance to the Gregory filling (what
// the comparison's distance colouring shows); returns the largest |distance|.
double apply_distance(const DrawScene& gregory, DrawScene& gb) {
  double max_distance = 0;
  for (std::size_t i = 0; i < gb.surfaces.size(); ++i) {
    const SurfaceMesh& to = gregory.surfaces.at(i);
    gb.surfaces[i].mean =
        signed_distance_to(gb.surfaces[i].positions, {to.positions, to.normals, to.triangles});
    for (double v : gb.surfaces[i].mean) max_distance = std::max(max_distance, std::abs(v));
  }
  return max_distance;
}

// The comparison: the Gregory filling shaded with the network, the GB filling coloured by its
// signed distance to the Gregory one, and the distance legend in the column at the right.
TEST(CompareGolden, DistanceColouringAndLegend) {
  PATCHLAB_REQUIRE_GL();
  const DrawScene gregory = test::file_draw_scene(test::asset("default.json"), FaceScheme::Gregory);
  DrawScene gb = test::file_draw_scene(test::asset("default.json"), FaceScheme::GB);
  const double m = apply_distance(gregory, gb);
  ASSERT_GT(m, 0);
  SceneRenderer renderer;
  const GpuScene left(gregory), right(gb);
  FrameRequest r;
  r.width = 960;
  r.height = 400;
  r.settings = parse_display_mode("shaded+network");
  FramePanel& a = r.panels.emplace_back();
  a.scene = &left;
  a.label = "Gregory";
  FramePanel& b = r.panels.emplace_back();
  b.scene = &right;
  b.label = "Generalized Bézier";
  b.settings = parse_display_mode("mean+network");  // the field that holds the distance
  b.range = ColorRange{-m, m};
  r.legend = LegendSpec{"distance GB − Gregory", ColorRange{-m, m}};
  const DrawScene* scenes[] = {&gregory, &gb};
  r.camera = default_camera(scenes, panel_aspect(r));
  test::compare_with_golden("compare-distance", render_frame(renderer, r));
  // The legend stands in the column at the right, clear of both panels.
  const FrameLayout layout = frame_layout(r);
  ASSERT_TRUE(layout.legend);
  EXPECT_GE(layout.legend_x, layout.panels[1].x + layout.panels[1].width);
}

}  // namespace
}  // namespace pl
