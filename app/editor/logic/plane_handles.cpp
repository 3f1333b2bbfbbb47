#include "app/editor/logic/plane_handles.hpp"

#include <cmath>

#include "core/network/handle_planes.hpp"
#include "core/network/tangent_planes.hpp"

namespace pl {

namespace {

Vec3 unit_or_zero(const Vec3& x) {
  const double l = glm::length(x);
  return l > 0 ? x / l : Vec3(0);
}

}  // namespace

std::optional<VertexPlane> vertex_plane(const Network& n, int v) {
  if (v < 0 || v >= int(n.vertices.size())) return std::nullopt;
  VertexPlane plane;
  plane.fixed = !n.normals.empty() && n.normals[v].has_value();
  std::optional<Vec3> normal = handle_plane_normal(n, v);
  if (!normal) {
    const std::vector<int> edges = edges_at(n, v);
    if (edges.size() != 2) return std::nullopt;
    const Vec3 c = glm::cross(unit_or_zero(end_tangent(n, edges[0], v)),
                              unit_or_zero(end_tangent(n, edges[1], v)));
    // Nearly collinear tangents span no plane worth showing.
    if (!(glm::length(c) > 1e-6)) return std::nullopt;
    normal = glm::normalize(c);
  }
  plane.normal = *normal;
  if (glm::dot(plane.normal, corner_normal_sum(n, v)) < 0) plane.normal = -plane.normal;
  plane.normal += Vec3(0.0);  // -0 shown as 0 in the panel
  return plane;
}

std::vector<PlaneHandle> plane_handles(const Scene& scene, const Selection& selection,
                                       const Camera& camera, const ViewRect& rect,
                                       double ui_scale) {
  std::vector<PlaneHandle> out;
  if (!scene.network) return out;
  std::vector<int> vertices;
  for (const PointRef& r : selection.points())
    if (r.kind == PointRef::Kind::NetworkVertex) vertices.push_back(r.index);
  if (vertices.size() > kMaxPlaneHandles) return out;
  for (int v : vertices) {
    const auto plane = vertex_plane(*scene.network, v);
    if (!plane) continue;
    PlaneHandle h;
    h.vertex = v;
    h.centre = scene.network->vertices[v];
    h.normal = plane->normal;
    h.fixed = plane->fixed;
    const double wpp = world_per_pixel(camera, rect, h.centre) * ui_scale;
    h.radius = kPlaneDiscRadiusPx * wpp;
    h.knob = h.centre + kNormalHandlePx * wpp * h.normal;
    out.push_back(h);
  }
  return out;
}

int pick_knob(const std::vector<PlaneHandle>& handles, const Camera& camera, const ViewRect& rect,
              const Vec2& pixel, double radius_px) {
  int best = -1;
  double best_d = radius_px;
  for (std::size_t i = 0; i < handles.size(); ++i) {
    const auto q = project_to_window(camera, rect, handles[i].knob);
    if (!q) continue;
    const double d = glm::length(*q - pixel);
    if (d <= best_d) {
      best_d = d;
      best = int(i);
    }
  }
  return best;
}

std::optional<Vec3> dragged_normal(const PlaneHandle& h, const DragMotion& motion,
                                   const Camera& camera, const ViewRect& rect, const Vec2& pixel) {
  const Vec3 knob = motion.start + motion.offset(camera, rect, pixel, std::nullopt);
  const Vec3 d = knob - h.centre;
  const double l = glm::length(d);
  if (!(l > 1e-6 * h.radius) || !std::isfinite(l)) return std::nullopt;
  return d / l;
}

}  // namespace pl
