#include "app/editor/logic/live_surfaces.hpp"

#include <algorithm>
#include <chrono>

#include "render/draw_scene_builder.hpp"

namespace pl {

namespace {

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
  draw_.closed_orientation = closed_orientation(scene, evaluation_.surfaces(), draw_.surfaces);
  points_ = collect_scene_points(scene, evaluation_.surfaces(), &evaluation_.filling());
  ++points_layout_;
  fill_overlays(scene, points_, draw_);
  if (scene.network && curve_segments_.size() != scene.network->edges.size())
    curve_segments_.clear();  // new edges: every curve at full resolution until chosen again
  if (!curve_segments_.empty())
    for (std::size_t e = 0; e < curve_segments_.size(); ++e)
      if (curve_segments_[e] != kCurveSegments)
        draw_.network_curves[e] = edge_polyline(*scene.network, int(e), curve_segments_[e]);
  edge_points_.clear();
  if (scene.network)
    for (std::size_t e = 0; e < scene.network->edges.size(); ++e)
      edge_points_.push_back(edge_points(*scene.network, int(e)));
  // The free curves' points follow the network's and the surfaces' (collect_scene_points).
  curve_points_at_ = points_.positions.size();
  for (const SceneCurve& c : scene.curves) curve_points_at_ -= c.points.size();
  free_lines_.rebuild(scene.curves, draw_.free_curves);
}

bool LiveSurfaces::update_overlays(const Scene& scene, const std::vector<int>& changed) {
  const std::size_t vertices = scene.network ? scene.network->vertices.size() : 0;
  const std::size_t edges = scene.network ? scene.network->edges.size() : 0;
  const auto& surfaces = this->surfaces().surfaces;
  if (points_.face_group.size() != surfaces.size() ||
      points_.patch_group.size() != scene.patches.size() || edge_points_.size() != edges ||
      draw_.network_curves.size() != edges || vertices + 2 * edges > points_.positions.size())
    return false;
  if (scene.network) {
    const Network& net = *scene.network;
    for (std::size_t e = 0; e < edges; ++e) {
      const std::array<Vec3, 4> p = edge_points(net, int(e));
      if (p == edge_points_[e]) continue;  // O(E) comparisons; curves only where they moved
      edge_points_[e] = p;
      draw_.network_curves[e] = edge_polyline(net, int(e), segments_of(e));
      points_.positions[net.edges[e].v[0]] = p[0];
      points_.positions[vertices + 2 * e] = p[1];
      points_.positions[vertices + 2 * e + 1] = p[2];
      points_.positions[net.edges[e].v[1]] = p[3];
    }
    for (std::size_t v = 0; v < vertices; ++v)  // vertices on no edge
      points_.positions[v] = net.vertices[v];
  }
  for (int i : changed) {
    const SceneSurface& s = surfaces[i];
    if (s.face >= 0) {
      const int g = points_.face_group[i];
      if (g < 0 || !update_group(points_, std::size_t(g), s.evaluator->patch()) ||
          !update_free_points(points_, std::size_t(g), scene, s.evaluator->patch(),
                              evaluation_.filling(), cross_scratch_))
        return false;
    } else if (s.patch >= 0 && s.patch < int(scene.patches.size())) {
      if (!update_group(points_, std::size_t(points_.patch_group[s.patch]),
                        *scene.patches[s.patch].patch))
        return false;
    }
  }
  if (!free_lines_.update(scene.curves, draw_.free_curves)) return false;
  std::size_t at = curve_points_at_;
  for (const SceneCurve& c : scene.curves)
    for (const Vec3& p : c.points) {
      if (at >= points_.positions.size()) return false;
      points_.positions[at++] = p;
    }
  if (at != points_.positions.size()) return false;
  draw_.net.points = points_.positions;
  draw_.arrows = points_.arrows;
  return true;
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

std::vector<int> LiveSurfaces::sync(const Scene& scene, uint64_t revision,
                                    const InteriorEdit* known) {
  const auto t0 = std::chrono::steady_clock::now();
  const SyncStats stats = evaluation_.sync(scene, known);
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
