#include "core/network/tangent_planes.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "core/base/data_error.hpp"

namespace pl {

namespace {

std::string edge_handle_path(const Network& net, int e, int v) {
  const int k = net.edges[e].v[0] == v ? 0 : 1;
  return "network.edges[" + std::to_string(e) + "].handles[" + std::to_string(k) + "]";
}

// Size of the edge's control polygon: the scale a "zero" tangent is measured against.
double edge_extent(const Network& net, int e) {
  const BezierCurve c = net.edge_curve(e);
  double d = 0;
  for (const Vec3& p : c.control_points()) d = std::max(d, glm::length(p - c.control_points()[0]));
  return d;
}

bool used_by_a_face(const NetworkTopology& topo, int v) {
  for (int e : topo.vertex_edges[v])
    if (!topo.edge_faces[e].empty()) return true;
  return false;
}

// Least squares: a unit normal minimising sum (n . t_i)^2 is an eigenvector of the smallest
// eigenvalue of sum t_i t_i^T. When the smallest eigenvalues tie (three orthogonal tangents at a
// cube corner) every unit vector of their eigenspace is a minimiser, and the one closest to the
// faces' corner normals is taken. Returns 0 when the tangents are collinear (no plane).
Vec3 fitted_normal(const std::vector<Vec3>& unit, const Vec3& corners) {
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

}  // namespace

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
  // the reverse of the incoming side's (right-hand rule). Their sum orients the plane and
  // breaks ties of the least-squares fit.
  Vec3 corners(0);
  for (int e : topo.vertex_edges[v])
    for (const EdgeUse& use : topo.edge_faces[e]) {
      const auto& loop = net.faces[use.face].loop;
      const int sides = static_cast<int>(loop.size());
      if (loop[use.side] != v) continue;  // each corner at v has one side starting at v
      const int prev = topo.face_sides[use.face][(use.side + sides - 1) % sides].edge;
      const Vec3 out = end_tangent(net, e, v), back = end_tangent(net, prev, v);
      corners += glm::cross(glm::normalize(out), glm::normalize(back));
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
    n = fitted_normal(unit, corners);
    if (n == Vec3(0))
      throw DataError("", vpath,
                      "the end tangents of its edges are collinear, so they do not define a "
                      "tangent plane (give the vertex a normal)");
  }
  const double orient = glm::dot(n, corners);
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
