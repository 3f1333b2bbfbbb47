// Names one editable point of a scene: a network vertex, an edge handle, or a control point of
// an explicit patch. Derived points (Gregory twins, GB ribbons of network faces) are not
// editable: they follow the network.
#pragma once

#include <string>
#include <vector>

#include "core/scene/scene.hpp"

namespace pl {

struct PointRef {
  enum class Kind : uint8_t { NetworkVertex, EdgeHandle, PatchPoint, CurvePoint };
  Kind kind = Kind::NetworkVertex;
  int object = -1;  // edge (EdgeHandle), patch (PatchPoint) or curve (CurvePoint) index
  int index = -1;   // vertex index, handle 0/1, or control point index

  static PointRef vertex(int v) { return {Kind::NetworkVertex, -1, v}; }
  static PointRef handle(int edge, int which) { return {Kind::EdgeHandle, edge, which}; }
  static PointRef patch_point(int patch, int k) { return {Kind::PatchPoint, patch, k}; }
  // A control point of a free curve (scene.curves).
  static PointRef curve_point(int curve, int k) { return {Kind::CurvePoint, curve, k}; }
  bool operator==(const PointRef&) const = default;
};

bool point_exists(const Scene& scene, const PointRef& ref);
Vec3 point_position(const Scene& scene, const PointRef& ref);  // ref must exist
// Moves the point. Moving a network vertex also translates the edge handles attached to it, so
// the edges keep their shape near the vertex (what a designer expects when dragging a corner).
void set_point_position(Scene& scene, const PointRef& ref, const Vec3& p);
std::string describe(const PointRef& ref);  // "vertex 3", "edge 5 handle 1", "patch 0 point 7"

}  // namespace pl
