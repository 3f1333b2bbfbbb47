// Keeping a network G1-consistent while handles move: every end tangent at a vertex stays in
// the vertex's tangent plane, so the filling never has to project one (analyze reports no
// projected vertex) and faces sharing an edge stay G1 along it.
//   - A constrained handle move (the default of drags, nudges and typed coordinates) projects
//     the handle onto the plane through its vertex: the fixed normal's plane, or the plane fitted
//     to the vertex's other handles.
//   - A free move puts the handle where asked and turns the vertex's plane with it: the smallest
//     rotation that takes the plane to one containing the new tangent, applied to the vertex's
//     other handles (and to its fixed normal).
//   - Setting a vertex normal turns its handles with the plane the same way.
// Works on the network alone (no topology needed): what the document's commands and drags call.
#pragma once

#include <array>
#include <optional>
#include <span>

#include "core/network/tangent_planes.hpp"
#include "core/scene/network.hpp"

namespace pl {

// How a handle move treats its vertex's tangent plane.
enum class HandleMode {
  KeepPlane,    // the handle is projected onto the plane (default)
  RotatePlane,  // the handle goes where asked; the plane and the other handles turn with it
};

// The edges at vertex v, in edge order.
std::vector<int> edges_at(const Network& network, int v);

// The corner normals of the faces at v summed (right-hand rule: outgoing x incoming end
// tangent): which side of v's tangent plane its faces face, the filling's tie breaker.
Vec3 corner_normal_sum(const Network& network, int v);

// The normal of the plane handles at v are kept in: its fixed normal, else the least-squares
// plane of the end tangents of v's edges other than `skip` when those span a plane (ties broken
// by the faces' corners at v, as the filling does), else the plane of all of v's end tangents
// when those span one. None when v needs no plane: fewer than three edges and no fixed normal
// (two tangents always share a plane, so any move keeps G1) or collinear tangents. Unit,
// unoriented.
std::optional<Vec3> handle_plane_normal(const Network& network, int v,
                                        std::span<const int> skip = {});

// Where a constrained move of handle `end` (0, 1) of edge e towards `target` puts it: the target
// projected onto the plane through the vertex (handle_plane_normal, skipping the edges in
// `moving`, whose handles at that vertex move too, and e). A projection onto the vertex itself
// (a target along the normal) keeps the handle's current direction at the projected length
// (or leaves it where it is if that is zero).
Vec3 constrained_handle(const Network& network, int e, int end, const Vec3& target,
                        std::span<const int> moving = {});

// The free move: handle `end` of edge e goes to `target`; the other handles at its vertex and
// its fixed normal turn with the plane (see the header).
void move_handle_turning_plane(Network& network, int e, int end, const Vec3& target);

// Gives vertex v the fixed normal `normal` (non-zero) and turns its handles with the plane: the
// smallest rotation from its current plane (handle_plane_normal, sign chosen towards `normal`)
// to the new one. A vertex without a plane only gets the normal.
void turn_vertex_plane(Network& network, int v, const Vec3& normal);

// The handles of a new edge a -> b: at 1/3 and 2/3 of the chord, then each turned, keeping its
// length, into its vertex's plane where that is defined (handle_plane_normal of the existing
// edges). A chord along the normal keeps the chord's handle.
std::array<Vec3, 2> new_edge_handles(const Network& network, int a, int b);

// The unit normal of the tangent plane the faces using edge e share at parameter t: spanned by
// the edge's derivative and the Chiyokura–Kimura direction b(t) = (1 - t) b0 + t b3, oriented
// like the end vertices' planes. The fixed normal a split gives its new vertex.
Vec3 edge_plane_normal(const Network& network, const std::vector<TangentPlane>& planes, int e,
                       double t);

// The rotation taking unit vector `from` to unit vector `to` about their common perpendicular.
glm::dmat3 smallest_rotation(const Vec3& from, const Vec3& to);

}  // namespace pl
