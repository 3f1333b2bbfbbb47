#include "core/network/handle_planes.hpp"

#include <algorithm>
#include <cmath>

#include "core/scene/network_edit.hpp"

namespace pl {

namespace {

std::optional<Vec3> fixed_normal(const Network& n, int v) {
  if (n.normals.empty() || !n.normals[v]) return std::nullopt;
  return glm::normalize(*n.normals[v]);
}

Vec3 unit_or_zero(const Vec3& x) {
  const double l = glm::length(x);
  return l > 0 ? x / l : Vec3(0);
}

// The least-squares plane of the end tangents at v of its edges not in `skip`, if they span one.
std::optional<Vec3> plane_of_tangents(const Network& n, int v, std::span<const int> skip) {
  std::vector<Vec3> unit;
  for (int e : edges_at(n, v)) {
    if (std::find(skip.begin(), skip.end(), e) != skip.end()) continue;
    const Vec3 t = unit_or_zero(end_tangent(n, e, v));
    if (t != Vec3(0)) unit.push_back(t);
  }
  if (unit.size() < 2) return std::nullopt;
  const Vec3 normal = fit_plane_normal(unit, corner_normal_sum(n, v));
  if (normal == Vec3(0)) return std::nullopt;
  return normal;
}

// The plane of v as it is: fixed, or fitted to all its end tangents.
std::optional<Vec3> current_plane(const Network& n, int v) {
  if (auto f = fixed_normal(n, v)) return f;
  return plane_of_tangents(n, v, {});
}

Vec3& handle_at(Network& n, int e, int v) {
  NetworkEdge& ed = n.edges[e];
  return ed.handles[ed.v[0] == v ? 0 : 1];
}

}  // namespace

Vec3 corner_normal_sum(const Network& n, int v) {
  Vec3 sum(0);
  for (const NetworkFace& f : n.faces) {
    const int sides = int(f.loop.size());
    for (int i = 0; i < sides; ++i) {
      if (f.loop[i] != v) continue;
      const int out = edge_between(n, v, f.loop[(i + 1) % sides]);
      const int back = edge_between(n, f.loop[(i + sides - 1) % sides], v);
      if (out < 0 || back < 0) continue;
      sum +=
          glm::cross(unit_or_zero(end_tangent(n, out, v)), unit_or_zero(end_tangent(n, back, v)));
    }
  }
  return sum;
}

std::vector<int> edges_at(const Network& n, int v) {
  std::vector<int> out;
  for (std::size_t e = 0; e < n.edges.size(); ++e)
    if (n.edges[e].v[0] == v || n.edges[e].v[1] == v) out.push_back(int(e));
  return out;
}

glm::dmat3 smallest_rotation(const Vec3& from, const Vec3& to) {
  const Vec3 axis = glm::cross(from, to);
  const double s = glm::length(axis), c = glm::dot(from, to);
  if (!(s > 1e-15)) {
    if (c > 0) return glm::dmat3(1.0);
    // Half a turn about any axis perpendicular to `from`.
    const Vec3 p = unit_or_zero(std::fabs(from.x) < 0.9 ? glm::cross(from, Vec3(1, 0, 0))
                                                        : glm::cross(from, Vec3(0, 1, 0)));
    return 2.0 * glm::outerProduct(p, p) - glm::dmat3(1.0);
  }
  // Rodrigues: R = I + [k]x sin + [k]x^2 (1 - cos), with k = axis / s.
  const Vec3 k = axis / s;
  const glm::dmat3 kx(0, k.z, -k.y, -k.z, 0, k.x, k.y, -k.x, 0);  // column-major
  return glm::dmat3(1.0) + s * kx + (1 - c) * (kx * kx);
}

std::optional<Vec3> handle_plane_normal(const Network& n, int v, std::span<const int> skip) {
  if (auto f = fixed_normal(n, v)) return f;
  if (edges_at(n, v).size() < 3) return std::nullopt;
  if (auto p = plane_of_tangents(n, v, skip)) return p;
  return plane_of_tangents(n, v, {});
}

Vec3 constrained_handle(const Network& n, int e, int end, const Vec3& target,
                        std::span<const int> moving) {
  const int v = n.edges.at(e).v.at(end);
  std::vector<int> skip(moving.begin(), moving.end());
  skip.push_back(e);
  const auto normal = handle_plane_normal(n, v, skip);
  if (!normal) return target;
  const Vec3 p = n.vertices[v];
  const Vec3 d = target - p, in_plane = d - glm::dot(d, *normal) * *normal;
  const double len = glm::length(in_plane);
  if (len > 1e-9 * glm::length(d)) return p + in_plane;
  // Along the normal: keep the handle's direction in the plane.
  const Vec3 now = n.edges[e].handles[end] - p;
  const Vec3 dir = unit_or_zero(now - glm::dot(now, *normal) * *normal);
  return dir == Vec3(0) || !(len > 0) ? n.edges[e].handles[end] : p + len * dir;
}

void move_handle_turning_plane(Network& n, int e, int end, const Vec3& target) {
  const int v = n.edges.at(e).v.at(end);
  const bool fixed = fixed_normal(n, v).has_value();
  const auto normal = fixed || edges_at(n, v).size() >= 3 ? current_plane(n, v) : std::nullopt;
  const Vec3 p = n.vertices[v], before = n.edges[e].handles[end] - p;
  n.edges[e].handles[end] = target;
  const Vec3 t = target - p;
  if (!normal || !(glm::length(t) > 0)) return;
  // The plane turns by the smallest rotation that makes it contain t: from t's projection onto
  // the plane to t (or from the handle's old direction, when t is along the normal).
  Vec3 from = unit_or_zero(t - glm::dot(t, *normal) * *normal);
  if (from == Vec3(0)) from = unit_or_zero(before - glm::dot(before, *normal) * *normal);
  if (from == Vec3(0)) return;
  const glm::dmat3 r = smallest_rotation(from, glm::normalize(t));
  for (int other : edges_at(n, v))
    if (other != e) {
      Vec3& h = handle_at(n, other, v);
      h = p + r * (h - p);
    }
  if (fixed) n.normals[v] = stored_normal(r * *normal);
}

void turn_vertex_plane(Network& n, int v, const Vec3& normal) {
  set_vertex_normal(n, v, normal);  // checks and normalises; refuses a zero normal
  const Vec3 to = *n.normals[v];
  n.normals[v] = std::nullopt;
  auto from = current_plane(n, v);
  n.normals[v] = to;
  if (!from) return;
  if (glm::dot(*from, to) < 0) from = -*from;
  const glm::dmat3 r = smallest_rotation(*from, to);
  const Vec3 p = n.vertices[v];
  for (int e : edges_at(n, v)) {
    Vec3& h = handle_at(n, e, v);
    h = p + r * (h - p);
  }
}

std::array<Vec3, 2> new_edge_handles(const Network& n, int a, int b) {
  const Vec3 pa = n.vertices.at(a), pb = n.vertices.at(b), chord = pb - pa;
  std::array<Vec3, 2> h{pa + chord / 3.0, pb - chord / 3.0};
  const int ends[2] = {a, b};
  for (int k = 0; k < 2; ++k) {
    const auto normal = current_plane(n, ends[k]);
    if (!normal) continue;
    const Vec3 p = n.vertices[ends[k]], d = h[k] - p;
    const Vec3 in_plane = d - glm::dot(d, *normal) * *normal;
    const double len = glm::length(in_plane);
    if (len > 1e-9 * glm::length(d)) h[k] = p + glm::length(d) / len * in_plane;
  }
  return h;
}

Vec3 edge_plane_normal(const Network& n, const std::vector<TangentPlane>& planes, int e, double t) {
  const BezierCurve c = n.edge_curve(e);
  const auto& p = c.control_points();
  const NetworkEdge& ed = n.edges.at(e);
  const Vec3 b0 = glm::normalize(glm::cross(planes.at(ed.v[0]).normal, 3.0 * (p[1] - p[0])));
  const Vec3 b3 = glm::normalize(glm::cross(planes.at(ed.v[1]).normal, 3.0 * (p[3] - p[2])));
  const Vec3 b = (1 - t) * b0 + t * b3;
  // c x b0 = c x (n0 x c) lies along n0: the plane's orientation follows the end planes'.
  return glm::normalize(glm::cross(c.evaluate(t).d1, b));
}

}  // namespace pl
