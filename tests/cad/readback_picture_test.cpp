// The picture of the docs: a scene exported to STEP, read back by OpenCASCADE, tessellated by
// OpenCASCADE (BRepMesh) and drawn by PatchLab's renderer next to PatchLab's own tessellation of
// the same scene, with isophotes (they show any normal error of a fit). The two panels are also
// compared pixel by pixel: drawn alone with the same camera they must agree but for a few pixels
// where a stripe edge moves by a pixel. The picture adds the borders: PatchLab's patches on the
// left, the file's faces (one per piece: split n-gons, whole quadrilaterals) on the right. Skipped
// without OpenGL, like the render tests. PATCHLAB_UPDATE_DOCS_IMAGES=1 writes the picture to
// docs/images/.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <random>

#include "render/draw_scene_builder.hpp"
#include "app/cli/load_input.hpp"
#include "cad_test_util.hpp"
#include "core/cad/cad_export.hpp"
#include "core/cad/occt_io.hpp"
#include "core/cad/occt_mesh.hpp"
#include "core/io/atomic_file.hpp"
#include "render/egl_context.hpp"
#include "render/frame.hpp"

namespace pl::test {
namespace {

TEST(CadPicture, StepReadBackDrawsLikePatchLab) {
  std::unique_ptr<EglContext> context;
  try {
    context = std::make_unique<EglContext>();
  } catch (const GlContextError& e) {
    GTEST_SKIP() << "no OpenGL: " << e.what();
  }
  const auto file = source_dir() / "assets/gregory-blob-closed.json";
  const Scene scene = load_scene_file(file);
  const auto step = std::filesystem::temp_directory_path() /
                    ("patchlab-picture-" + std::to_string(std::random_device()()) + ".step");
  CadExportOptions options;
  options.source = file.string();
  const CadExportReport report = export_cad(scene, step, options);
  const CadFile back = read_cad_file(step, CadFormat::Step);
  std::filesystem::remove(step);

  DrawScene ours = [&] {
    TessellationCache cache;
    return build_draw_scene(scene, evaluate_scene(scene, 48, std::nullopt, cache, file), 0);
  }();
  DrawScene theirs;
  theirs.surfaces = occt_meshes(back.shape, 2e-4 * report.size);
  theirs.borders = occt_edge_polylines(back.shape);  // the faces of the file: one per piece
  ASSERT_EQ(theirs.surfaces.size(), report.faces.size());

  FrameRequest request;
  request.width = 1600;
  request.height = 700;
  request.settings.base = BaseMode::Isophotes;
  const Box box = ours.bounds();
  SceneRenderer renderer;
  GpuScene gpu_ours(ours), gpu_theirs(theirs);

  // Each alone, same camera: the difference.
  {
    FrameRequest one = request;
    one.width = 800;
    one.camera =
        preset_camera(ViewPreset::Iso, box, panel_aspect(800, 700, 1, one.settings, one.range));
    one.panels = {{&gpu_ours, ""}};
    const Image a = render_frame(renderer, one);
    one.panels = {{&gpu_theirs, ""}};
    const Image b = render_frame(renderer, one);
    ASSERT_EQ(a.rgba.size(), b.rgba.size());
    std::size_t differing = 0, pixels = a.rgba.size() / 4;
    for (std::size_t i = 0; i < pixels; ++i) {
      int d = 0;
      for (int c = 0; c < 3; ++c)
        d = std::max(d, std::abs(int(a.rgba[4 * i + c]) - int(b.rgba[4 * i + c])));
      if (d > 48) ++differing;
    }
    std::printf("STEP read back vs PatchLab: %zu of %zu pixels differ by more than 48/255\n",
                differing, pixels);
    EXPECT_LT(differing, pixels / 100);
  }

  // The picture: with the borders of PatchLab's patches (left) and of the file's faces (right).
  request.settings.borders = true;
  request.camera = preset_camera(
      ViewPreset::Iso, box,
      panel_aspect(request.width, request.height, 2, request.settings, request.range));
  request.panels = {{&gpu_ours, "PatchLab"}, {&gpu_theirs, "STEP read back, OpenCASCADE mesh"}};
  const Image picture = render_frame(renderer, request);
  const auto out = std::filesystem::temp_directory_path() / "patchlab-cad-export-readback.png";
  write_file_atomically(out, encode_png(picture));
  std::printf("picture: %s\n", out.c_str());
  if (const char* u = std::getenv("PATCHLAB_UPDATE_DOCS_IMAGES"); u && std::string(u) == "1")
    write_file_atomically(source_dir() / "docs/images/cad-export-readback.png",
                          encode_png(picture));
}

}  // namespace
}  // namespace pl::test
