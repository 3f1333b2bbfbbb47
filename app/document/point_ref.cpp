#include "app/document/point_ref.hpp"

#include <cassert>

namespace pl {

bool point_exists(const Scene& s, const PointRef& r) {
  switch (r.kind) {
    case PointRef::Kind::NetworkVertex:
      return s.network && r.index >= 0 && r.index < int(s.network->vertices.size());
    case PointRef::Kind::EdgeHandle:
      return s.network && r.object >= 0 && r.object < int(s.network->edges.size()) &&
             (r.index == 0 || r.index == 1);
    case PointRef::Kind::PatchPoint:
      return r.object >= 0 && r.object < int(s.patches.size()) && r.index >= 0 &&
             r.index < int(s.patches[r.object].patch->size());
    case PointRef::Kind::CurvePoint:
      return r.object >= 0 && r.object < int(s.curves.size()) && r.index >= 0 &&
             r.index < int(s.curves[r.object].points.size());
  }
  return false;
}

Vec3 point_position(const Scene& s, const PointRef& r) {
  assert(point_exists(s, r));
  switch (r.kind) {
    case PointRef::Kind::NetworkVertex:
      return s.network->vertices[r.index];
    case PointRef::Kind::EdgeHandle:
      return s.network->edges[r.object].handles[r.index];
    case PointRef::Kind::PatchPoint:
      return s.patches[r.object].patch->control_point(r.index);
    case PointRef::Kind::CurvePoint:
      return s.curves[r.object].points[r.index];
  }
  return Vec3(0);
}

void set_point_position(Scene& s, const PointRef& r, const Vec3& p) {
  assert(point_exists(s, r));
  switch (r.kind) {
    case PointRef::Kind::NetworkVertex: {
      Network& n = *s.network;
      const Vec3 d = p - n.vertices[r.index];
      n.vertices[r.index] = p;
      for (NetworkEdge& e : n.edges)
        for (int end = 0; end < 2; ++end)
          if (e.v[end] == r.index) e.handles[end] += d;
      break;
    }
    case PointRef::Kind::EdgeHandle:
      s.network->edges[r.object].handles[r.index] = p;
      break;
    case PointRef::Kind::PatchPoint: {
      // Copy on write: undo snapshots of the scene share patch objects, so a patch is never
      // changed in place.
      auto& slot = s.patches[r.object].patch;
      std::shared_ptr<Patch> copy = slot->clone();
      copy->set_control_point(r.index, p);
      slot = std::move(copy);
      break;
    }
    case PointRef::Kind::CurvePoint:
      // Any position keeps a curve valid (weights and knots are untouched).
      s.curves[r.object].points[r.index] = p;
      break;
  }
}

std::string describe(const PointRef& r) {
  switch (r.kind) {
    case PointRef::Kind::NetworkVertex:
      return "vertex " + std::to_string(r.index);
    case PointRef::Kind::EdgeHandle:
      return "edge " + std::to_string(r.object) + " handle " + std::to_string(r.index);
    case PointRef::Kind::PatchPoint:
      return "patch " + std::to_string(r.object) + " point " + std::to_string(r.index);
    case PointRef::Kind::CurvePoint:
      return "curve " + std::to_string(r.object) + " point " + std::to_string(r.index);
  }
  return "?";
}

}  // namespace pl
