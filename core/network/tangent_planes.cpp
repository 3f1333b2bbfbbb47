#include "core/network/tangent_planes.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>

#include "core/base/data_error.hpp"

namespace pl {

namespace {

std::string edge_handle_path(const Network& net, int e, int v) {
  const int k = net.edges[e].v[0] == v ? 0 : 1;
  return "network.edges[" + std::to_string(e) + "].handles[" + std::to_string(k) + "]";
}

// The edge's control points (no allocation: planes are computed for every vertex of a network).
std::array<Vec3, 4> control_points(const Network& net, int e) {
  const NetworkEdge& ed = net.edges[e];
  return {net.vertices[ed.v[0]], ed.handles[0], ed.handles[1], net.vertices[ed.v[1]]};
}

// Size of the edge's control polygon: the scale a "zero" tangent is measured against.
double edge_extent(const Network& net, int e) {
  const std::array<Vec3, 4> p = control_points(net, e);
  double d = 0;
  for (const Vec3& q : p) d = std::max(d, glm::length(q - p[0]));
  return d;
}

// The right-hand (Newell) normal of a face's boundary control polygon: which way the face faces,
// whatever its corners do (a reflex corner's own normal points the other way).
Vec3 face_polygon_normal(const Network& net, const NetworkTopology& topo, int f) {
  // Points relative to the first one: the sum is then translation-invariant (no cancellation
  // far from the origin), and each term is a product of two point differences, finite for every
  // coordinate the readers accept; its length is taken after scaling by the largest component,
  // as the squared length of a sum of such products can overflow.
  Vec3 n(0), first(0), previous(0);
  bool started = false;
  for (const FaceSide& side : topo.face_sides[f]) {
    const std::array<Vec3, 4> pts = control_points(net, side.edge);
    for (int j = 0; j < 3; ++j) {
      const Vec3& p = pts[side.reversed ? 3 - j : j];
      if (started)
        n += glm::cross(previous - first, p - first);
      else
        first = p;
      started = true;
      previous = p;
    }
  }
  const double largest = std::max({std::abs(n.x), std::abs(n.y), std::abs(n.z)});
  if (!(largest > 0) || !std::isfinite(largest)) return Vec3(0);
  return glm::normalize(n / largest);
}

bool used_by_a_face(const NetworkTopology& topo, int v) {
  for (int e : topo.vertex_edges[v])
    if (!topo.edge_faces[e].empty()) return true;
  return false;
}

}  // namespace

// Least squares: a unit normal minimising sum (n . t_i)^2 is an eigenvector of the smallest
// eigenvalue of sum t_i t_i^T. When the smallest eigenvalues tie (three orthogonal tangents at a
// cube corner) every unit vector of their eigenspace is a minimiser, and the one closest to the
// faces' corner normals is taken. Returns 0 when the tangents are collinear (no plane).
Vec3 fit_plane_normal(const std::vector<Vec3>& unit, const Vec3& corners) {
  Eigen::Matrix3d m = Eigen::Matrix3d::Zero();
  for (const Vec3& t : unit) {
    const Eigen::Vector3d x(t.x, t.y, t.z);
    m += x * x.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(m);
  const Eigen::Vector3d lambda = eig.eigenvalues();  // ascending
  const double tie = 1e-9 * lambda.sum();
  if (!(lambda(1) > tie)) return Vec3(0);
  const auto col = [&](int i) {
    const Eigen::Vector3d x = eig.eigenvectors().col(i);
    return Vec3(x(0), x(1), x(2));
  };
  Vec3 n = col(0);
  if (lambda(2) - lambda(0) < tie) {
    n = corners;
  } else if (lambda(1) - lambda(0) < tie) {
    n = glm::dot(corners, col(0)) * col(0) + glm::dot(corners, col(1)) * col(1);
  }
  return glm::length(n) > 1e-12 ? glm::normalize(n) : glm::normalize(col(0));
}

Vec3 end_tangent(const Network& net, int e, int v) {
  const NetworkEdge& ed = net.edges.at(e);
  return ed.v[0] == v ? 3.0 * (ed.handles[0] - net.vertices[v])
                      : 3.0 * (ed.handles[1] - net.vertices[v]);
}

TangentPlane vertex_tangent_plane(const Network& net, const NetworkTopology& topo, int v) {
  TangentPlane plane;
  if (!used_by_a_face(topo, v)) return plane;
  const std::string vpath = "network.vertices[" + std::to_string(v) + "]";
  std::vector<Vec3> unit;
  for (int e : topo.vertex_edges[v]) {
    const Vec3 t = end_tangent(net, e, v);
    const double len = glm::length(t);
    if (!(len > 1e-12 * edge_extent(net, e)))
      throw DataError("", edge_handle_path(net, e, v),
                      "the handle coincides with vertex " + std::to_string(v) +
                          ", so the edge has no end tangent there");
    unit.push_back(t / len);
  }
  // The faces' outward normals at their corners at v: the outgoing side's tangent crossed with
  // the reverse of the incoming side's (right-hand rule). Their sum breaks ties of the
  // least-squares fit. The plane is oriented by the faces' own normals: at a vertex where a
  // reflex corner (an L-shaped face's) meets a convex one, the corner normals cancel and their
  // sum's sign is rounding, which would turn the plane over and fold the faces along its edges.
  Vec3 corners(0), faces(0);
  for (int e : topo.vertex_edges[v])
    for (const EdgeUse& use : topo.edge_faces[e]) {
      const auto& loop = net.faces[use.face].loop;
      const int sides = static_cast<int>(loop.size());
      if (loop[use.side] != v) continue;  // each corner at v has one side starting at v
      const int prev = topo.face_sides[use.face][(use.side + sides - 1) % sides].edge;
      const Vec3 out = end_tangent(net, e, v), back = end_tangent(net, prev, v);
      corners += glm::cross(glm::normalize(out), glm::normalize(back));
      faces += face_polygon_normal(net, topo, use.face);
    }
  Vec3 n(0);
  if (!net.normals.empty() && net.normals[v]) {
    n = *net.normals[v];
    const double len = glm::length(n);
    if (!(len > 0))
      throw DataError("", "network.normals[" + std::to_string(v) + "]",
                      "a normal must not be the zero vector");
    n /= len;
  } else {
    n = fit_plane_normal(unit, corners);
    if (n == Vec3(0))
      throw DataError("", vpath,
                      "the end tangents of its edges are collinear, so they do not define a "
                      "tangent plane (give the vertex a normal)");
  }
  const double orient = glm::dot(n, faces);
  if (orient < 0) n = -n;
  plane.normal = n;
  plane.defined = true;
  for (std::size_t k = 0; k < unit.size(); ++k) {
    const Vec3& t = unit[k];
    const double off = std::fabs(glm::dot(t, n));
    const double in = glm::length(t - glm::dot(t, n) * n);
    if (!(in > 1e-9))
      throw DataError(
          "", edge_handle_path(net, topo.vertex_edges[v][k], v),
          "the edge leaves vertex " + std::to_string(v) + " normal to the vertex's tangent plane");
    plane.max_projection_deg = std::max(plane.max_projection_deg, std::atan2(off, in) * 180 / M_PI);
  }
  return plane;
}

std::vector<TangentPlane> vertex_tangent_planes(const Network& net, const NetworkTopology& topo) {
  std::vector<TangentPlane> planes(net.vertices.size());
  for (std::size_t v = 0; v < planes.size(); ++v)
    planes[v] = vertex_tangent_plane(net, topo, static_cast<int>(v));
  return planes;
}

std::vector<ProjectedVertex> projected_vertices(const std::vector<TangentPlane>& planes) {
  std::vector<ProjectedVertex> out;
  for (std::size_t v = 0; v < planes.size(); ++v)
    if (planes[v].defined && planes[v].max_projection_deg > kProjectionReportDeg)
      out.push_back({static_cast<int>(v), planes[v].max_projection_deg});
  return out;
}

}  // namespace pl
