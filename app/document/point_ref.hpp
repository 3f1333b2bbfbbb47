// Names one editable point of a scene: a network vertex, an edge handle, a control point of an
// explicit patch or of a free curve, or a free interior point of a network GB face. Derived
// points (Gregory twins, the G1 rows of GB faces) are not editable: they follow the network.
#pragma once

#include <string>
#include <vector>

#include "core/scene/scene.hpp"

namespace pl {

struct PointRef {
  enum class Kind : uint8_t { NetworkVertex, EdgeHandle, PatchPoint, CurvePoint, FreePoint };
  Kind kind = Kind::NetworkVertex;
  int object = -1;  // edge (EdgeHandle), patch (PatchPoint), curve (CurvePoint) or face index
  int index = -1;   // vertex index, handle 0/1, control point index, or side (-1: the centre)
  int j = -1, layer = -1;  // FreePoint: point j of ribbon layer `layer` of side `index`

  static PointRef vertex(int v) { return {Kind::NetworkVertex, -1, v}; }
  static PointRef handle(int edge, int which) { return {Kind::EdgeHandle, edge, which}; }
  static PointRef patch_point(int patch, int k) { return {Kind::PatchPoint, patch, k}; }
  // A control point of a free curve (scene.curves).
  static PointRef curve_point(int curve, int k) { return {Kind::CurvePoint, curve, k}; }
  // A free interior point of network GB face `face` (core/network/gb_face_free_points.hpp),
  // named as its offset would be (the centre, or [side, j, layer]).
  static PointRef free_point(int face, const InteriorOffset& name) {
    return name.centre ? PointRef{Kind::FreePoint, face, -1, -1, -1}
                       : PointRef{Kind::FreePoint, face, name.side, name.j, name.layer};
  }
  InteriorOffset interior_name() const {  // FreePoint only
    return index < 0 ? InteriorOffset{.centre = true}
                     : InteriorOffset{.side = index, .j = j, .layer = layer};
  }
  bool operator==(const PointRef&) const = default;
};

bool point_exists(const Scene& scene, const PointRef& ref);
Vec3 point_position(const Scene& scene, const PointRef& ref);  // ref must exist
// Moves the point. Moving a network vertex also translates the edge handles attached to it, so
// the edges keep their shape near the vertex (what a designer expects when dragging a corner).
// A free point stores offset = p - its default position (the entry removed when that is zero).
void set_point_position(Scene& scene, const PointRef& ref, const Vec3& p);
// "vertex 3", "edge 5 handle 1", "patch 0 point 7", "face 2 free point [1,2,2]", "face 2 centre"
std::string describe(const PointRef& ref);

// Free points. The default position of free point `ref` in the scene as it is (the face's G1 data
// rebuilt from the tangent planes at its vertices: the cost of one face after a validation of the
// network), and the stored offset of the point set directly (a drag whose defaults do not move).
Vec3 free_point_default(const Scene& scene, const PointRef& ref);
void set_free_point_offset(Scene& scene, const PointRef& ref, const Vec3& offset);
// Whether network face f is filled as a GB face (the faces that have free points).
bool is_gb_face(const Scene& scene, int face);

}  // namespace pl
