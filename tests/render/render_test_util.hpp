// Shared pieces of the render tests: one offscreen context for the whole test program (tests
// that need it are SKIPPED, never passed, when none can be made) and canonical scenes built
// straight from the core, without the app.
#pragma once

#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "app/cli/load_input.hpp"
#include "core/domain/tessellation_cache.hpp"
#include "core/eval/patch_evaluator.hpp"
#include "core/mesh/surface_mesh.hpp"
#include "core/patch/bezier_patch.hpp"
#include "render/default_view.hpp"
#include "render/draw_scene.hpp"
#include "render/draw_scene_builder.hpp"
#include "render/egl_context.hpp"
#include "render/frame.hpp"
#include "render/gpu_scene.hpp"
#include "render/scene_renderer.hpp"

namespace pl::test {

// nullptr (with the reason in *why) when this machine cannot make a GL 3.3 core context.
inline EglContext* shared_context(std::string* why = nullptr) {
  static std::string reason;
  static std::unique_ptr<EglContext> context = [] {
    try {
      return std::make_unique<EglContext>();
    } catch (const GlContextError& e) {
      reason = e.what();
      return std::unique_ptr<EglContext>();
    }
  }();
  if (why) *why = reason;
  return context.get();
}

#define PATCHLAB_REQUIRE_GL()                                                      \
  do {                                                                             \
    std::string why_;                                                              \
    if (!::pl::test::shared_context(&why_)) GTEST_SKIP() << "no OpenGL: " << why_; \
  } while (0)

inline SurfaceMesh bezier_mesh(int m, int n, std::vector<Vec3> points, int density,
                               const std::string& name = "patch") {
  auto patch = std::make_shared<BezierPatch>(m, n, std::move(points));
  static TessellationCache cache;
  PatchEvaluator ev(patch, cache.get(patch->domain(), density));
  return make_surface_mesh(ev, name);
}

// The corners of the square [lo, hi]^2 at height z, as a bilinear patch's control points.
inline std::vector<Vec3> square_corners(double lo, double hi, double z) {
  std::vector<Vec3> p;
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) p.emplace_back(lo + (hi - lo) * i, lo + (hi - lo) * j, z);
  return p;
}

// The square [-half, half]^2 at height z, as a bilinear patch's mesh.
inline SurfaceMesh floor_square(double half, double z = 0, const std::string& name = "floor") {
  std::vector<Vec3> corners;
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) corners.emplace_back(-half + 2 * half * i, -half + 2 * half * j, z);
  return bezier_mesh(1, 1, corners, 4, name);
}

// A one-panel frame of `scene` (uploaded as `gpu`) with these settings: the colour range
// automatic over its surfaces, the camera the default view (as `patchlab render` without
// --view) or a preset.
inline FrameRequest one_panel(const GpuScene& gpu, const DrawScene& scene,
                              const DisplaySettings& settings, int width, int height,
                              std::optional<ViewPreset> view = {}) {
  FrameRequest r;
  r.width = width;
  r.height = height;
  r.settings = settings;
  r.panels.emplace_back().scene = &gpu;
  std::vector<const SurfaceMesh*> meshes;
  for (const SurfaceMesh& m : scene.surfaces) meshes.push_back(&m);
  r.range = automatic_range(meshes, settings.curvature);
  const DrawScene* scenes[] = {&scene};
  r.camera = view ? preset_camera(*view, scene.bounds(), panel_aspect(r))
                  : default_camera(scenes, panel_aspect(r));
  return r;
}

// z = (x^2 + y^2) / 2 over [-1, 1]^2, exactly, as a biquadratic patch: x = 2u - 1 is linear in u,
// and x^2 has Bernstein coefficients (1, -1, 1).
inline std::vector<Vec3> paraboloid_points() {
  const double c[3] = {1, -1, 1};
  std::vector<Vec3> p;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) p.emplace_back(-1 + i, -1 + j, 0.5 * (c[i] + c[j]));
  return p;
}

// A bicubic saddle z = 0.45 (x^2 - y^2) over [-1, 1]^2 (the bezier-saddle asset).
inline std::vector<Vec3> saddle_points() {
  std::vector<Vec3> p;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      const double x = -1 + 2.0 * i / 3, y = -1 + 2.0 * j / 3;
      p.emplace_back(x, y, 0.45 * (x * x - y * y));
    }
  // Bernstein coefficients of x^2 on [-1,1] are not the samples; the lifted inner points make it
  // a genuine saddle-like bicubic either way.
  return p;
}

// A scene file (.json or .gbp) as the `render` command draws it (no combs), or with one filling
// scheme for its network faces.
inline DrawScene file_draw_scene(const std::string& path, std::optional<FaceScheme> scheme = {},
                                 int density = 24) {
  const Scene scene = load_scene_file(path);
  static TessellationCache cache;
  return build_draw_scene(scene, evaluate_scene(scene, density, scheme, cache, path), 0);
}

inline std::string asset(const std::string& name) {
  return std::string(PATCHLAB_SOURCE_DIR) + "/assets/" + name;
}

}  // namespace pl::test
