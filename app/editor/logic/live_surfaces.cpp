#include "app/editor/logic/live_surfaces.hpp"

#include <algorithm>
#include <chrono>

#include "app/cli/draw_scene_builder.hpp"

namespace pl {

namespace {

// The points collect_scene_points lists for a surface after the network's: every point of an
// explicit patch, the derived (non-boundary) points of a face.
bool own_point(const SceneSurface& s, std::size_t k) {
  return s.face < 0 || s.evaluator->patch().kind(k) != ControlPointKind::Boundary;
}

std::array<Vec3, 4> edge_points(const Network& net, int e) {
  const NetworkEdge& ed = net.edges[e];
  return {net.vertices[ed.v[0]], ed.handles[0], ed.handles[1], net.vertices[ed.v[1]]};
}

}  // namespace

LiveSurfaces::LiveSurfaces(const Scene& scene, int density, std::optional<FaceScheme> scheme,
                           const std::string& source, uint64_t revision, SampleStorage storage)
    : evaluation_(scene, density, scheme, source, storage), revision_(revision) {
  for (const SceneSurface& s : evaluation_.surfaces().surfaces)
    draw_.surfaces.push_back(make_surface_mesh(*s.evaluator, s.name));
  rebuild_overlays(scene);
}

std::size_t LiveSurfaces::sample_count() const {
  std::size_t n = 0;
  for (const SceneSurface& s : surfaces().surfaces) n += s.evaluator->sample_count();
  return n;
}

int LiveSurfaces::segments_of(std::size_t edge) const {
  return edge < curve_segments_.size() ? curve_segments_[edge] : kCurveSegments;
}

void LiveSurfaces::rebuild_overlays(const Scene& scene) {
  points_ = collect_scene_points(scene, evaluation_.surfaces());
  fill_overlays(scene, points_, draw_);
  if (scene.network && curve_segments_.size() != scene.network->edges.size())
    curve_segments_.clear();  // new edges: every curve at full resolution until chosen again
  if (!curve_segments_.empty())
    for (std::size_t e = 0; e < curve_segments_.size(); ++e)
      if (curve_segments_[e] != kCurveSegments)
        draw_.network_curves[e] = edge_polyline(*scene.network, int(e), curve_segments_[e]);
  // The layout of collect_scene_points: vertices, two handles per edge, then each surface's own
  // points in surface order.
  std::size_t at = 0;
  edge_points_.clear();
  if (scene.network) {
    at = scene.network->vertices.size() + 2 * scene.network->edges.size();
    for (std::size_t e = 0; e < scene.network->edges.size(); ++e)
      edge_points_.push_back(edge_points(*scene.network, int(e)));
  }
  surface_points_.clear();
  for (const SceneSurface& s : evaluation_.surfaces().surfaces) {
    std::size_t count = 0;
    for (std::size_t k = 0; k < s.evaluator->patch().size(); ++k) count += own_point(s, k);
    surface_points_.emplace_back(at, count);
    at += count;
  }
  // Then the free curves' points, curve after curve.
  curve_points_at_ = at;
  for (const SceneCurve& c : scene.curves) at += c.points.size();
  free_lines_.rebuild(scene.curves, draw_.free_curves);
  if (at != points_.positions.size()) surface_points_.clear();  // an unknown layout
}

bool LiveSurfaces::update_overlays(const Scene& scene, const std::vector<int>& changed) {
  const std::size_t vertices = scene.network ? scene.network->vertices.size() : 0;
  const std::size_t edges = scene.network ? scene.network->edges.size() : 0;
  if (surface_points_.size() != surfaces().surfaces.size() || edge_points_.size() != edges ||
      draw_.network_curves.size() != edges || draw_.net.points.size() != points_.positions.size())
    return false;
  const auto set = [&](std::size_t i, const Vec3& p) {
    points_.positions[i] = p;
    draw_.net.points[i] = p;
  };
  if (scene.network) {
    const Network& net = *scene.network;
    if (vertices + 2 * edges > points_.positions.size()) return false;
    for (std::size_t e = 0; e < edges; ++e) {
      const std::array<Vec3, 4> p = edge_points(net, int(e));
      if (p == edge_points_[e]) continue;  // O(E) comparisons; curves only where they moved
      edge_points_[e] = p;
      draw_.network_curves[e] = edge_polyline(net, int(e), segments_of(e));
      set(net.edges[e].v[0], p[0]);
      set(vertices + 2 * e, p[1]);
      set(vertices + 2 * e + 1, p[2]);
      set(net.edges[e].v[1], p[3]);
    }
    for (std::size_t v = 0; v < vertices; ++v)  // vertices on no edge
      if (points_.positions[v] != net.vertices[v]) set(v, net.vertices[v]);
  }
  for (int i : changed) {
    const SceneSurface& s = surfaces().surfaces[i];
    auto [at, count] = surface_points_[i];
    std::size_t n = 0;
    for (std::size_t k = 0; k < s.evaluator->patch().size(); ++k)
      if (own_point(s, k)) {
        if (n++ == count) return false;
        set(at++, s.evaluator->patch().control_point(k));
      }
    if (n != count) return false;
  }
  if (!free_lines_.update(scene.curves, draw_.free_curves)) return false;
  std::size_t at = curve_points_at_;
  for (const SceneCurve& c : scene.curves)
    for (const Vec3& p : c.points) {
      if (at >= points_.positions.size()) return false;
      if (points_.positions[at] != p) set(at, p);
      ++at;
    }
  return at == points_.positions.size();
}

void LiveSurfaces::update_meshes(const SyncStats& stats) {
  const auto& surfaces = evaluation_.surfaces().surfaces;
  std::vector<bool> changed(surfaces.size(), false);
  for (int i : stats.changed_surfaces) changed[i] = true;
  if (stats.renumbered) {
    // Unchanged meshes move with their surfaces; the rest are made again.
    std::vector<SurfaceMesh> meshes(surfaces.size());
    for (std::size_t i = 0; i < surfaces.size(); ++i) {
      const int from = stats.previous_surface.at(i);
      if (!changed[i] || (from >= 0 && from < int(draw_.surfaces.size()) &&
                          draw_.surfaces[from].revision == surfaces[i].evaluator->revision() &&
                          draw_.surfaces[from].name == surfaces[i].name))
        meshes[i] = std::move(draw_.surfaces.at(from));
      else
        meshes[i] = make_surface_mesh(*surfaces[i].evaluator, surfaces[i].name);
    }
    draw_.surfaces = std::move(meshes);
    return;
  }
  for (std::size_t i = 0; i < surfaces.size(); ++i)
    if (changed[i]) draw_.surfaces[i] = make_surface_mesh(*surfaces[i].evaluator, surfaces[i].name);
}

std::vector<int> LiveSurfaces::sync(const Scene& scene, uint64_t revision) {
  const auto t0 = std::chrono::steady_clock::now();
  const SyncStats stats = evaluation_.sync(scene);
  update_meshes(stats);
  if (stats.renumbered || !update_overlays(scene, stats.changed_surfaces)) rebuild_overlays(scene);
  revision_ = revision;
  last_sync_ms_ =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return stats.changed_surfaces;
}

std::vector<int> LiveSurfaces::set_densities(std::span<const int> densities) {
  const SyncStats stats = evaluation_.set_densities(densities);
  update_meshes(stats);
  return stats.changed_surfaces;
}

bool LiveSurfaces::set_curve_segments(std::vector<int> per_edge) {
  if (per_edge.size() != edge_points_.size() || per_edge.size() != draw_.network_curves.size())
    return false;
  bool changed = false;
  for (std::size_t e = 0; e < per_edge.size(); ++e) {
    per_edge[e] = std::max(1, per_edge[e]);
    if (per_edge[e] == segments_of(e)) continue;
    const auto& p = edge_points_[e];  // as last synced
    draw_.network_curves[e] = curve_polyline(BezierCurve({p[0], p[1], p[2], p[3]}), per_edge[e]);
    changed = true;
  }
  curve_segments_ = std::move(per_edge);
  return changed;
}

std::vector<int> LiveSurfaces::densities() const {
  std::vector<int> d;
  for (const SceneSurface& s : surfaces().surfaces)
    d.push_back(s.evaluator->tessellation().density);
  return d;
}

}  // namespace pl
