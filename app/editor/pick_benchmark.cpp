#include "app/editor/pick_benchmark.hpp"

#include <chrono>
#include <cstdio>

#include "app/document/scene_file.hpp"
#include "app/editor/logic/preferences.hpp"
#include "app/editor/logic/scene_picker.hpp"
#include "app/editor/logic/surface_probe.hpp"
#include "core/base/data_error.hpp"
#include "core/network/sample_networks.hpp"
#include "render/draw_scene_builder.hpp"

namespace pl {

namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

// What the picker reads from a view, built one surface at a time (no evaluator is kept: only
// the meshes the editor would draw), plus the points and curves.
struct PickData {
  std::vector<SurfaceMesh> meshes;
  std::vector<SelectionItem> items;
  std::vector<Polyline> curves;
  ScenePoints points;
  PickScene scene() const { return {meshes, items, curves, &points, {}}; }
};

PickData pick_data(const Scene& scene, int density) {
  PickData d;
  // The points need the filled patches only: a density-1 evaluation is enough for them.
  TessellationCache cache;
  const SceneSurfaces coarse = evaluate_scene(scene, 1, std::nullopt, cache, "bench");
  d.points = collect_scene_points(scene, coarse);
  d.items = surface_items(coarse);
  for (const SceneSurface& s : coarse.surfaces) {
    const PatchEvaluator ev(s.evaluator->patch().clone(),
                            cache.get(s.evaluator->patch().domain(), density));
    d.meshes.push_back(make_surface_mesh(ev, s.name));
  }
  if (scene.network) d.curves = network_polylines(*scene.network);
  return d;
}

struct Figures {
  double first_ms = 0, mean_ms = 0, surface_ms = 0, brute_ms = 0;
  std::size_t triangles = 0, hits = 0, hierarchies = 0, memory = 0;
};

// Picks at a grid of cursor positions over the scene in a 1280x720 view framing it.
Figures measure(const PickData& d, bool brute_force) {
  Figures f;
  for (const SurfaceMesh& m : d.meshes) f.triangles += m.triangles.size();
  const ViewRect rect{0, 0, 1280, 720};
  Box box;
  for (const SurfaceMesh& m : d.meshes)
    for (const Vec3& p : m.positions) box.add(p);
  const Camera camera = preset_camera(ViewPreset::Iso, box, rect.aspect());
  ScenePicker picker;
  const PickScene scene = d.scene();
  auto t0 = Clock::now();
  picker.pick(scene, camera, rect, Vec2(640, 360));
  f.first_ms = ms_since(t0);
  // Cursor positions over the scene's screen box (most of them on a surface, as a designer's).
  Vec2 lo(rect.width, rect.height), hi(0, 0);
  for (int c = 0; c < 8; ++c) {
    const Vec3 corner((c & 1 ? box.hi : box.lo).x, (c & 2 ? box.hi : box.lo).y,
                      (c & 4 ? box.hi : box.lo).z);
    if (const auto p = project_to_window(camera, rect, corner)) {
      lo = glm::min(lo, *p);
      hi = glm::max(hi, *p);
    }
  }
  lo = glm::max(lo, Vec2(0)), hi = glm::min(hi, Vec2(rect.width, rect.height));
  constexpr int kNx = 24, kNy = 14;
  std::vector<Vec2> pixels;
  for (int j = 0; j < kNy; ++j)
    for (int i = 0; i < kNx; ++i)
      pixels.emplace_back(lo.x + (hi.x - lo.x) * (i + 0.5) / kNx,
                          lo.y + (hi.y - lo.y) * (j + 0.5) / kNy);
  // Once to build what the hover would have built, then measured.
  for (const Vec2& p : pixels) picker.pick(scene, camera, rect, p);
  t0 = Clock::now();
  for (const Vec2& p : pixels) f.hits += picker.pick(scene, camera, rect, p).item.has_value();
  f.mean_ms = ms_since(t0) / double(pixels.size());
  t0 = Clock::now();
  for (const Vec2& p : pixels) picker.cast(d.meshes, window_ray(camera, rect, p));
  f.surface_ms = ms_since(t0) / double(pixels.size());
  if (brute_force) {
    constexpr int kRays = 8;
    t0 = Clock::now();
    for (int k = 0; k < kRays; ++k)
      probe_surfaces(d.meshes, window_ray(camera, rect, pixels[k * pixels.size() / kRays]));
    f.brute_ms = ms_since(t0) / kRays;
  }
  f.hierarchies = picker.stats().hierarchies;
  f.memory = picker.stats().memory_bytes;
  return f;
}

}  // namespace

int run_pick_benchmark(const std::optional<std::filesystem::path>& file, std::ostream& out,
                       std::ostream& err) {
  const int density = default_preferences().fine_density;
  Scene large, small;
  try {
    if (file) {
      large = load_scene_file(*file);
    } else {
      large.network = cube_sphere_network(16, FaceScheme::GB);
    }
  } catch (const DataError& e) {
    err << "patchlab: " << e.what() << "\n";
    return 1;
  }
  small.network = cube_sphere_network(2, FaceScheme::GB);
  const Figures s = measure(pick_data(small, density), false);
  const PickData data = pick_data(large, density);
  const Figures l = measure(data, true);
  char line[256];
  std::snprintf(line, sizeof line,
                "# density %d; %zu surfaces, %zu triangles, %zu points, %zu curves; %zu of 336 "
                "picks hit something; %zu hierarchies built\n",
                density, data.meshes.size(), l.triangles, data.points.positions.size(),
                data.curves.size(), l.hits, l.hierarchies);
  out << line;
  std::snprintf(line, sizeof line, "figure pick_first_ms %.3f ms\n", l.first_ms);
  out << line;
  std::snprintf(line, sizeof line, "figure pick_ms_24_faces %.4f ms\n", s.mean_ms);
  out << line;
  std::snprintf(line, sizeof line, "figure pick_ms_%zu_faces %.4f ms\n", data.meshes.size(),
                l.mean_ms);
  out << line;
  std::snprintf(line, sizeof line, "figure pick_surface_ms_%zu_faces %.4f ms\n", data.meshes.size(),
                l.surface_ms);
  out << line;
  std::snprintf(line, sizeof line, "figure pick_every_triangle_ms %.3f ms\n", l.brute_ms);
  out << line;
  std::snprintf(line, sizeof line, "figure pick_hierarchy_mb %.2f MB\n", l.memory / 1048576.0);
  out << line;
  out.flush();
  return 0;
}

}  // namespace pl
