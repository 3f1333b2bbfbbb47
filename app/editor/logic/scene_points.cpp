#include "app/editor/logic/scene_points.hpp"

#include "app/cli/draw_scene_builder.hpp"
#include "core/patch/bezier_patch.hpp"

namespace pl {

namespace {

uint32_t add(ScenePoints& s, const Vec3& p, ControlPointKind kind, std::optional<PointRef> ref) {
  s.positions.push_back(p);
  s.kinds.push_back(kind);
  s.refs.push_back(ref);
  return static_cast<uint32_t>(s.positions.size() - 1);
}

}  // namespace

std::vector<bool> ScenePoints::editable() const {
  std::vector<bool> e(refs.size());
  for (std::size_t i = 0; i < refs.size(); ++i) e[i] = refs[i].has_value();
  return e;
}

int ScenePoints::find(const PointRef& ref) const {
  for (std::size_t i = 0; i < refs.size(); ++i)
    if (refs[i] && *refs[i] == ref) return static_cast<int>(i);
  return -1;
}

ScenePoints collect_scene_points(const Scene& scene, const SceneSurfaces& surfaces) {
  ScenePoints s;
  if (scene.network) {
    const Network& net = *scene.network;
    std::vector<uint32_t> vertex_ids;
    for (std::size_t v = 0; v < net.vertices.size(); ++v)
      vertex_ids.push_back(add(s, net.vertices[v], ControlPointKind::Boundary,
                               PointRef::vertex(static_cast<int>(v))));
    for (std::size_t e = 0; e < net.edges.size(); ++e) {
      const NetworkEdge& edge = net.edges[e];
      const int ei = static_cast<int>(e);
      const uint32_t h1 =
          add(s, edge.handles[0], ControlPointKind::Boundary, PointRef::handle(ei, 0));
      const uint32_t h2 =
          add(s, edge.handles[1], ControlPointKind::Boundary, PointRef::handle(ei, 1));
      if (edge.v[0] >= 0 && edge.v[0] < int(vertex_ids.size()))
        s.segments.push_back({vertex_ids[edge.v[0]], h1});
      s.segments.push_back({h1, h2});
      if (edge.v[1] >= 0 && edge.v[1] < int(vertex_ids.size()))
        s.segments.push_back({h2, vertex_ids[edge.v[1]]});
    }
  }
  int explicit_index = 0;
  for (const SceneSurface& surface : surfaces.surfaces) {
    const Patch& p = surface.evaluator->patch();
    if (surface.face < 0) {
      // An explicit patch: all of its points are the user's.
      const auto base = static_cast<uint32_t>(s.positions.size());
      for (std::size_t k = 0; k < p.size(); ++k)
        add(s, p.control_point(k), p.kind(k),
            PointRef::patch_point(explicit_index, static_cast<int>(k)));
      if (const auto* b = dynamic_cast<const BezierPatch*>(&p)) {
        const int m = b->degree_u(), n = b->degree_v();
        auto id = [&](int i, int j) { return base + static_cast<uint32_t>(i * (n + 1) + j); };
        for (int i = 0; i <= m; ++i)
          for (int j = 0; j <= n; ++j) {
            if (i < m) s.segments.push_back({id(i, j), id(i + 1, j)});
            if (j < n) s.segments.push_back({id(i, j), id(i, j + 1)});
          }
      }
      ++explicit_index;
      continue;
    }
    // A network face: its boundary points are the network's (listed above); the rest are
    // derived from the network and only shown.
    for (std::size_t k = 0; k < p.size(); ++k)
      if (p.kind(k) != ControlPointKind::Boundary)
        add(s, p.control_point(k), p.kind(k), std::nullopt);
  }
  return s;
}

void fill_overlays(const Scene& scene, const ScenePoints& points, DrawScene& draw) {
  draw.net.points = points.positions;
  draw.net.kinds = points.kinds;
  draw.net.segments = points.segments;
  draw.network_curves.clear();
  if (scene.network) draw.network_curves = network_polylines(*scene.network);
  draw.free_curves.clear();
  for (const SceneCurve& c : scene.curves) draw.free_curves.push_back(free_curve_polyline(c));
}

}  // namespace pl
