#include "core/network/gb_face_free_points.hpp"

#include <algorithm>

#include "core/network/gb_face_interior.hpp"

namespace pl {

std::vector<InteriorOffset> gb_face_free_point_names(int n, int d) {
  std::vector<InteriorOffset> out{InteriorOffset{.centre = true}};
  for (int k = 2; k < gb_face_layers(d); ++k)
    for (int i = 0; i < n; ++i)
      for (int j = k; j <= d - 1 - k; ++j)
        out.push_back(InteriorOffset{.side = i, .j = j, .layer = k});
  return out;
}

bool same_interior_point(int n, int d, const InteriorOffset& a, const InteriorOffset& b) {
  if (a.centre || b.centre) return a.centre == b.centre;
  return interior_point_index(n, d, a) == interior_point_index(n, d, b);
}

std::vector<FreePoint> gb_face_free_points(const FaceRibbons& ribbons, int d,
                                           std::span<const InteriorOffset> offsets) {
  const int n = static_cast<int>(ribbons.sides.size());
  const std::vector<Vec3> net = gb_face_default_net(ribbons, d);
  std::vector<FreePoint> out;
  for (const InteriorOffset& name : gb_face_free_point_names(n, d)) {
    FreePoint p{name, net[interior_point_index(n, d, name)], Vec3(0)};
    for (const InteriorOffset& o : offsets)
      if (same_interior_point(n, d, o, name)) p.offset = o.by;
    out.push_back(p);
  }
  return out;
}

FaceRibbons face_ribbons_from_planes(const Network& net, const NetworkTopology& topo,
                                     const std::vector<TangentPlane>& planes, int f,
                                     std::vector<EdgeCrossTangents>& cross) {
  if (cross.size() < net.edges.size()) cross.resize(net.edges.size());
  for (const FaceSide& side : topo.face_sides.at(f))
    cross[side.edge] = edge_cross_tangents(net, topo, planes, side.edge);
  return face_ribbons(net, topo, cross, f);
}

FaceRibbons local_face_ribbons(const Network& net, const NetworkTopology& topo, int f) {
  std::vector<TangentPlane> planes(net.vertices.size());
  for (int v : net.faces.at(f).loop) planes[v] = vertex_tangent_plane(net, topo, v);
  std::vector<EdgeCrossTangents> cross;
  return face_ribbons_from_planes(net, topo, planes, f, cross);
}

std::vector<InteriorOffset> with_offset(int n, int d, std::vector<InteriorOffset> offsets,
                                        const InteriorOffset& name, const Vec3& by) {
  std::erase_if(offsets,
                [&](const InteriorOffset& o) { return same_interior_point(n, d, o, name); });
  if (by != Vec3(0)) {
    InteriorOffset o = name;
    o.by = by;
    offsets.push_back(o);
  }
  return offsets;
}

}  // namespace pl
