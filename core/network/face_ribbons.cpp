#include "core/network/face_ribbons.hpp"

#include <cassert>

#include "core/network/tangent_planes.hpp"

namespace pl {

FaceRibbons face_ribbons(const Network& net, const NetworkTopology& topo,
                         const std::vector<EdgeCrossTangents>& cross, int f) {
  FaceRibbons r;
  const int n = static_cast<int>(net.faces[f].loop.size());
  r.sides.resize(n);
  for (int i = 0; i < n; ++i) {
    const FaceSide& fs = topo.face_sides[f][i];
    const auto& uses = topo.edge_faces[fs.edge];
    std::size_t u = 0;
    while (uses[u].face != f || uses[u].side != i) ++u;
    assert(u < uses.size());
    const auto& a = cross[fs.edge].fields.at(u);
    const BezierCurve curve = net.edge_curve(fs.edge);
    const auto& pts = curve.control_points();
    CubicRibbon& rib = r.sides[i];
    for (int j = 0; j < 4; ++j) {
      // A reversed side runs the edge backwards: same cross vectors, mirrored parameter.
      const int k = fs.reversed ? 3 - j : j;
      rib.boundary[j] = pts[k];
      rib.inner[j] = pts[k] + a[k] / 3.0;
    }
  }
  // The row ends are the neighbouring sides' handles, exactly (not P + 3 (h - P) / 3), so that
  // patches sharing corner points see one value.
  for (int i = 0; i < n; ++i) {
    r.sides[i].inner[0] = r.sides[(i + n - 1) % n].boundary[2];
    r.sides[i].inner[3] = r.sides[(i + 1) % n].boundary[1];
  }
  return r;
}

std::vector<FaceRibbons> build_face_ribbons(const Network& net, const NetworkTopology& topo,
                                            std::vector<ProjectedVertex>& projected) {
  const std::vector<TangentPlane> planes = vertex_tangent_planes(net, topo);
  std::vector<EdgeCrossTangents> cross(net.edges.size());
  for (std::size_t e = 0; e < net.edges.size(); ++e)
    cross[e] = edge_cross_tangents(net, topo, planes, static_cast<int>(e));
  std::vector<FaceRibbons> out;
  out.reserve(net.faces.size());
  for (std::size_t f = 0; f < net.faces.size(); ++f)
    out.push_back(face_ribbons(net, topo, cross, static_cast<int>(f)));
  projected = projected_vertices(planes);
  return out;
}

}  // namespace pl
