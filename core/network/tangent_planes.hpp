// Tangent planes of a curve network's vertices: the plane every face's cross-boundary tangents
// at that vertex are built in (scene-format.md). From network.normals[v] when given, else the
// plane best fitting the unit end tangents of the edges at v (least squares).
#pragma once

#include <string>
#include <vector>

#include "core/scene/network.hpp"

namespace pl {

struct TangentPlane {
  Vec3 normal{0};                 // unit; oriented by the faces' right-hand rule around v
  double max_projection_deg = 0;  // largest angle between an end tangent at v and the plane
  bool defined = false;           // false for vertices no face uses (no plane is needed)
};

// A vertex whose edge end tangents had to be projected onto its plane (analyze reports it).
struct ProjectedVertex {
  int vertex = -1;
  double max_angle_deg = 0;  // largest angle by which an edge end tangent left the plane
};

// An end tangent further off its plane than this is reported as projected. Tangents that lie in
// the plane come out of the least-squares fit ~1e-14 degrees off, from rounding alone.
inline constexpr double kProjectionReportDeg = 1e-9;

// Tangent of edge e leaving vertex v (e must be incident to v): 3 (handle - vertex), the
// derivative of the edge curve run away from v with parameter in [0, 1].
Vec3 end_tangent(const Network& network, int edge, int vertex);

// The unit normal of the least-squares plane through unit tangents (minimising the sum of
// (n . t)^2); ties between equally good planes go to the one closest to `tie_breaker` (the
// faces' corner normals at the vertex). 0 when the tangents are collinear (no plane). Unoriented.
Vec3 fit_plane_normal(const std::vector<Vec3>& unit_tangents, const Vec3& tie_breaker);

// The plane at vertex v. Throws DataError (empty source) naming the vertex, normal or edge
// when it is undefined: end tangents of zero length, all collinear, or one normal to the plane.
TangentPlane vertex_tangent_plane(const Network& network, const NetworkTopology& topology, int v);

// Planes of every vertex; the ones no face uses are left undefined.
std::vector<TangentPlane> vertex_tangent_planes(const Network& network,
                                                const NetworkTopology& topology);

// The vertices whose end tangents had to be projected (max_projection_deg above the threshold).
std::vector<ProjectedVertex> projected_vertices(const std::vector<TangentPlane>& planes);

}  // namespace pl
