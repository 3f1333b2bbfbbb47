// Renderer benchmark: prints "figure NAME VALUE UNIT" lines.
//   frame time (median ms) of a ~200k-triangle patch at 1280x720 in isophote and curvature mode,
//   the same at a tiny viewport (vertex-bound: the difference is the fragment share),
//   the upload of one drag update (positions, normals, curvatures of that patch).
// --quick: tiny sizes, proves the program runs (CI smoke test); figures meaningless.
// Without a GL context it says so and exits 0, as the render tests skip.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <vector>

#include "core/domain/tessellation_cache.hpp"
#include "core/eval/patch_evaluator.hpp"
#include "core/patch/bezier_patch.hpp"
#include "render/egl_context.hpp"
#include "render/gpu_scene.hpp"
#include "render/offscreen_target.hpp"
#include "render/scene_renderer.hpp"

namespace {

void figure(const char* name, double value, const char* unit) {
  std::printf("figure %s %.6g %s\n", name, value, unit);
  std::fflush(stdout);
}

// Median wall time in ms; `f` must finish its GPU work (glFinish) to be measured honestly.
double median_ms(int repeats, const std::function<void()>& f) {
  std::vector<double> t;
  for (int i = 0; i < repeats; ++i) {
    const auto a = std::chrono::steady_clock::now();
    f();
    const auto b = std::chrono::steady_clock::now();
    t.push_back(std::chrono::duration<double, std::milli>(b - a).count());
  }
  std::nth_element(t.begin(), t.begin() + t.size() / 2, t.end());
  return t[t.size() / 2];
}

// A bicubic with enough relief that every display mode has something to show.
std::vector<pl::Vec3> wave_points() {
  std::vector<pl::Vec3> p;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      const double x = -1 + 2.0 * i / 3, y = -1 + 2.0 * j / 3;
      p.emplace_back(x, y, 0.4 * (x * x - y * y) + ((i == 1 && j == 2) ? 0.6 : 0.0));
    }
  return p;
}

}  // namespace

int main(int argc, char** argv) {
  const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
  const int density = quick ? 16 : 316;  // 2 * 316^2 = 199712 triangles
  const int width = quick ? 64 : 1280, height = quick ? 36 : 720;
  const int repeats = quick ? 2 : 15;

  std::unique_ptr<pl::EglContext> context;
  try {
    context = std::make_unique<pl::EglContext>();
  } catch (const pl::GlContextError& e) {
    std::printf("no OpenGL context, nothing measured: %s\n", e.what());
    return 0;
  }
  std::printf("renderer: %s (EGL %s), LLVMPIPE_NUM_THREADS=%s\n",
              reinterpret_cast<const char*>(glGetString(GL_RENDERER)), context->platform().c_str(),
              std::getenv("LLVMPIPE_NUM_THREADS") ? std::getenv("LLVMPIPE_NUM_THREADS") : "unset");

  auto patch = std::make_shared<pl::BezierPatch>(3, 3, wave_points());
  pl::TessellationCache cache;
  pl::PatchEvaluator evaluator(patch, cache.get(patch->domain(), density));
  pl::DrawScene scene;
  scene.surfaces.push_back(pl::make_surface_mesh(evaluator, "wave"));
  figure("render_triangles", static_cast<double>(scene.surfaces[0].triangles.size()), "count");

  pl::SceneRenderer renderer;
  pl::GpuScene gpu(scene);
  const pl::Camera camera =
      pl::preset_camera(pl::ViewPreset::Iso, scene.bounds(), double(width) / height);
  std::vector<const pl::SurfaceMesh*> meshes{&scene.surfaces[0]};

  for (int samples : {4, 0}) {
    pl::OffscreenTarget target(width, height, samples);
    for (const char* mode : {"isophotes", "mean"}) {
      const pl::DisplaySettings settings = pl::parse_display_mode(mode);
      const pl::ColorRange range = pl::automatic_range(meshes, settings.curvature);
      auto frame = [&](int w, int h) {
        target.bind();
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        renderer.draw_backdrop({0, 0, w, h, 1.0});
        renderer.draw(gpu, camera, settings, range, {0, 0, w, h, 1.0});
        glFinish();
      };
      frame(width, height);  // warm-up: shader compilation happens at first use on llvmpipe
      const std::string tag = std::string(mode) + (samples ? "_msaa4" : "_nomsaa");
      figure(("render_frame_" + tag).c_str(), median_ms(repeats, [&] { frame(width, height); }),
             "ms");
      // The same geometry into a 1/16-area viewport: close to the vertex and setup cost alone.
      figure(("render_frame_small_viewport_" + tag).c_str(),
             median_ms(repeats, [&] { frame(width / 4, height / 4); }), "ms");
    }
  }

  // One drag update: the core moved a control point; re-upload that patch's attributes.
  pl::SurfaceMesh& mesh = scene.surfaces[0];
  int step = 0;
  figure("render_drag_upload",
         median_ms(repeats,
                   [&] {
                     for (auto& p : mesh.positions) p.z += (++step % 2 ? 1e-3 : -1e-3);
                     ++mesh.revision;
                     gpu.update_surface(0, mesh);
                     glFinish();
                   }),
         "ms");
  figure("render_drag_upload_bytes",
         static_cast<double>(mesh.positions.size() * (3 + 3 + 4) * sizeof(float)), "bytes");
  return 0;
}
