#include "app/editor/logic/scene_picker.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pl {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// A curve (or a vertex) lies on the surfaces it bounds, but they are drawn as chords of the exact
// surface: a point up to this many pixels (in world size at its depth) behind the surface hit
// still counts as visible. The renderer pulls curves forward for the same reason.
constexpr double kCurveDepthSlackPx = 4.0;

// Distance from p to the segment ab in the plane, and the parameter of the nearest point.
std::pair<double, double> segment_distance(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 d = b - a;
  const double len2 = glm::dot(d, d);
  const double s = len2 > 0 ? std::clamp(glm::dot(p - a, d) / len2, 0.0, 1.0) : 0.0;
  return {glm::length(p - (a + s * d)), s};
}

Box bounds_of(std::span<const Vec3> points) {
  Box b;
  for (const Vec3& p : points) b.add(p);
  return b;
}

}  // namespace

std::vector<SelectionItem> surface_items(const SceneSurfaces& surfaces) {
  std::vector<SelectionItem> items;
  items.reserve(surfaces.surfaces.size());
  for (const SceneSurface& s : surfaces.surfaces)
    items.push_back(s.face >= 0 ? SelectionItem::face(s.face) : SelectionItem::patch(s.patch));
  return items;
}

void ScenePicker::refresh(std::span<const SurfaceMesh> meshes) {
  cache_.resize(meshes.size());
  for (std::size_t i = 0; i < meshes.size(); ++i) {
    const SurfaceMesh& m = meshes[i];
    Entry& e = cache_[i];
    if (e.mesh == &m && e.revision == m.revision && e.vertices == m.positions.size() &&
        e.triangles == m.triangles.size())
      continue;
    e.mesh = &m;
    e.revision = m.revision;
    e.vertices = m.positions.size();
    e.triangles = m.triangles.size();
    e.box = bounds_of(m.positions);
    e.bvh.reset();
  }
}

std::optional<SurfaceHit> ScenePicker::cast(std::span<const SurfaceMesh> meshes, const Ray& ray) {
  refresh(meshes);
  // The boxes the ray enters, nearest entry first.
  std::vector<std::pair<double, int>> entered;
  for (std::size_t i = 0; i < cache_.size(); ++i)
    if (const auto t = intersect_box(ray, cache_[i].box, kInfinity))
      entered.emplace_back((*t)[0], static_cast<int>(i));
  std::sort(entered.begin(), entered.end());
  std::optional<SurfaceHit> best;
  double t_max = kInfinity;
  for (const auto& [t_enter, i] : entered) {
    if (t_enter >= t_max) break;  // every further box starts behind the hit
    Entry& e = cache_[i];
    const SurfaceMesh& m = meshes[i];
    if (!e.bvh) e.bvh = std::make_unique<TriangleBvh>(m.positions, m.triangles);
    if (const auto h = e.bvh->intersect(ray, m.positions, m.triangles, t_max)) {
      t_max = h->t;
      best = SurfaceHit{i, *h, ray.origin + h->t * ray.direction};
    }
  }
  return best;
}

PickResult ScenePicker::pick(const PickScene& scene, const Camera& camera, const ViewRect& rect,
                             const Vec2& pixel, const PickOptions& options) {
  PickResult r;
  const Ray ray = window_ray(camera, rect, pixel);
  r.surface = cast(scene.meshes, ray);
  const WindowProjector project(camera, rect);
  const Vec3 eye = camera.eye(), forward = camera.forward();
  // World size of a pixel at depth z along the view (constant for orthographic views).
  const double pixel_per_depth = 2 * std::tan(0.5 * camera.fov_y) / rect.height;
  auto world_per_px = [&](double z) {
    return camera.orthographic ? pixel_per_depth * camera.distance : pixel_per_depth * z;
  };
  // Whether p may lie within `radius_px` of the cursor: its distance to the ray against the
  // radius at its distance along the ray, which is at least its depth (a cheap test that
  // spares projecting points far from the cursor).
  auto near_ray = [&](const Vec3& p, double radius_px) {
    const Vec3 w = p - ray.origin;
    const double t = glm::dot(w, ray.direction);
    const double reach = 1.5 * radius_px * world_per_px(std::max(t, 0.0)) + 1e-12;
    return glm::dot(w, w) - t * t <= reach * reach || t <= 0;
  };

  const double surface_t = r.surface ? r.surface->hit.t : kInfinity;
  if (options.points && scene.points) {
    const ScenePoints& pts = *scene.points;
    // Editable points first: a derived point next to a vertex must not block grabbing it; and
    // among editable points those in front of the surface first (one drawn on top of the
    // surface at the cursor beats one behind it that happens to be nearer on screen). One pass
    // keeps the best of each kind.
    NearestPoint in_front, behind, derived;
    for (std::size_t i = 0; i < pts.positions.size(); ++i) {
      if (!pts.shown(i)) continue;  // left out of the drawing where too dense
      const Vec3& p = pts.positions[i];
      if (!camera.orthographic && !near_ray(p, options.point_radius_px)) continue;
      const auto s = project(p);
      if (!s) continue;
      const double d = glm::length(*s - pixel);
      if (d > options.point_radius_px) continue;
      const double z = glm::dot(p - eye, forward);
      if (!pts.refs[i]) {
        derived.offer(static_cast<int>(i), d, z);
      } else {
        const double t = glm::dot(p - ray.origin, ray.direction);
        const bool hidden = t > surface_t + kCurveDepthSlackPx * world_per_px(z);
        (hidden ? behind : in_front).offer(static_cast<int>(i), d, z);
      }
    }
    const int editable = in_front.index >= 0 ? in_front.index : behind.index;
    if (editable >= 0) {
      r.point = editable;
      r.item = SelectionItem::of_point(*pts.refs[r.point]);
    } else if (derived.index >= 0) {
      r.point = derived.index;
      r.derived_point = true;
    }
  }

  // The nearest line within the radius, network edges (when shown) and free curves alike.
  double best = options.curve_radius_px;
  auto offer_line = [&](const Polyline& line, auto&& take) {
    if (line.size() < 2) return;
    // Cull: the ray must pass within the pick radius (in world size at the far side of the
    // curve's box) of the box.
    Box box = bounds_of(line);
    const double far = glm::dot(box.centre() - eye, forward) + box.radius();
    const double margin = options.curve_radius_px * world_per_px(std::max(far, 0.0));
    box.lo -= Vec3(margin);
    box.hi += Vec3(margin);
    if (!intersect_box(ray, box, kInfinity)) return;
    std::optional<Vec2> a = project(line[0]);
    for (std::size_t k = 1; k < line.size(); ++k) {
      const std::optional<Vec2> b = project(line[k]);
      if (a && b) {
        const auto [d, s] = segment_distance(pixel, *a, *b);
        if (d < best) {
          const Vec3 p = line[k - 1] + s * (line[k] - line[k - 1]);
          const double depth = glm::dot(p - ray.origin, ray.direction);
          const double slack = kCurveDepthSlackPx * world_per_px(glm::dot(p - eye, forward));
          if (depth <= surface_t + slack) {
            best = d;
            take((double(k - 1) + s) / double(line.size() - 1), p);
          }
        }
      }
      a = b;
    }
  };
  if (options.curves)
    for (std::size_t e = 0; e < scene.curves.size(); ++e)
      offer_line(scene.curves[e], [&](double t, const Vec3&) {
        r.edge = static_cast<int>(e);
        r.edge_t = t;
      });
  for (std::size_t c = 0; c < scene.free_curves.size(); ++c)
    offer_line(scene.free_curves[c], [&](double, const Vec3& p) {
      r.edge = -1;  // nearer than every edge offered before
      r.curve = static_cast<int>(c);
      r.curve_point = p;
    });

  if (!r.item && r.curve >= 0) r.item = SelectionItem::curve(r.curve);
  if (!r.item && r.edge >= 0) r.item = SelectionItem::edge(r.edge);
  if (!r.item && r.surface && r.surface->surface < int(scene.surface_items.size()))
    r.item = scene.surface_items[r.surface->surface];
  return r;
}

std::optional<Vec2> find_pixel_for(ScenePicker& picker, const PickScene& scene,
                                   const Camera& camera, const ViewRect& rect,
                                   const SelectionItem& item, const PickOptions& options) {
  // Candidate points: the curve's samples, or the centres of the surfaces' triangles.
  std::vector<Vec3> candidates;
  if (item.kind == SelectionItem::Kind::Edge || item.kind == SelectionItem::Kind::Curve) {
    const auto lines = item.kind == SelectionItem::Kind::Edge ? scene.curves : scene.free_curves;
    if (item.index < 0 || item.index >= int(lines.size())) return std::nullopt;
    const Polyline& line = lines[item.index];
    for (std::size_t k = 1; k + 1 < line.size(); ++k) candidates.push_back(line[k]);
  } else {
    for (std::size_t s = 0; s < scene.meshes.size() && s < scene.surface_items.size(); ++s) {
      if (scene.surface_items[s] != item) continue;
      const SurfaceMesh& m = scene.meshes[s];
      for (const auto& t : m.triangles)
        candidates.push_back((m.positions[t[0]] + m.positions[t[1]] + m.positions[t[2]]) / 3.0);
    }
  }
  std::vector<Vec2> pixels;
  Vec2 middle(0);
  for (const Vec3& p : candidates)
    if (const auto px = project_to_window(camera, rect, p); px && rect.contains(*px)) {
      pixels.push_back(*px);
      middle += *px;
    }
  if (pixels.empty()) return std::nullopt;
  middle /= double(pixels.size());
  std::sort(pixels.begin(), pixels.end(), [&](const Vec2& a, const Vec2& b) {
    return glm::length(a - middle) < glm::length(b - middle);
  });
  // Nearest the middle first; a few hundred tries are plenty (each is a full pick).
  const std::size_t stride = std::max<std::size_t>(1, pixels.size() / 400);
  for (std::size_t i = 0; i < pixels.size(); i += stride) {
    const PickResult r = picker.pick(scene, camera, rect, pixels[i], options);
    if (r.item == item && r.point < 0) return pixels[i];
  }
  return std::nullopt;
}

ScenePicker::Stats ScenePicker::stats() const {
  Stats s;
  s.surfaces = cache_.size();
  for (const Entry& e : cache_)
    if (e.bvh) {
      ++s.hierarchies;
      s.memory_bytes += e.bvh->memory_bytes();
    }
  return s;
}

}  // namespace pl
