#include "app/document/point_ref.hpp"

#include <cassert>

#include "core/network/gb_face_free_points.hpp"

namespace pl {

namespace {

const NetworkFace& face_of(const Scene& s, const PointRef& r) {
  return s.network->faces[r.object];
}

}  // namespace

bool is_gb_face(const Scene& s, int f) {
  return s.network && f >= 0 && f < int(s.network->faces.size()) &&
         resolve_scheme(s.network->faces[f], std::nullopt) == FaceScheme::GB;
}

Vec3 free_point_default(const Scene& s, const PointRef& r) {
  assert(r.kind == PointRef::Kind::FreePoint && point_exists(s, r));
  const Network& net = *s.network;
  const NetworkFace& face = face_of(s, r);
  const NetworkTopology topo = validate_network(net, "scene");
  const InteriorOffset name = r.interior_name();
  for (const FreePoint& p :
       gb_face_free_points(local_face_ribbons(net, topo, r.object), face.degree, {}))
    if (same_interior_point(int(face.loop.size()), face.degree, p.name, name))
      return p.default_position;
  assert(false);
  return Vec3(0);
}

void set_free_point_offset(Scene& s, const PointRef& r, const Vec3& offset) {
  assert(r.kind == PointRef::Kind::FreePoint && point_exists(s, r));
  NetworkFace& face = s.network->faces[r.object];
  face.offsets = with_offset(int(face.loop.size()), face.degree, std::move(face.offsets),
                             r.interior_name(), offset);
}

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
    case PointRef::Kind::FreePoint: {
      if (!is_gb_face(s, r.object)) return false;
      const NetworkFace& f = face_of(s, r);
      return interior_offset_problem(int(f.loop.size()), f.degree, r.interior_name()).empty();
    }
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
    case PointRef::Kind::FreePoint: {
      const NetworkFace& f = face_of(s, r);
      Vec3 offset(0);
      for (const InteriorOffset& o : f.offsets)
        if (same_interior_point(int(f.loop.size()), f.degree, o, r.interior_name())) offset = o.by;
      return free_point_default(s, r) + offset;
    }
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
    case PointRef::Kind::FreePoint:
      set_free_point_offset(s, r, p - free_point_default(s, r));
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
    case PointRef::Kind::FreePoint:
      if (r.index < 0) return "face " + std::to_string(r.object) + " centre";
      return "face " + std::to_string(r.object) + " free point [" + std::to_string(r.index) + "," +
             std::to_string(r.j) + "," + std::to_string(r.layer) + "]";
  }
  return "?";
}

}  // namespace pl
