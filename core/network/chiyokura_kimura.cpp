#include "core/network/chiyokura_kimura.hpp"

#include "core/base/data_error.hpp"

namespace pl {

namespace {

Vec3 project(const Vec3& x, const Vec3& n) {
  return x - glm::dot(x, n) * n;
}

// The edge of face f adjacent to side `side` at vertex w (w is one end of that side).
int neighbour_edge(const Network& net, const NetworkTopology& topo, int f, int side, int w) {
  const auto& loop = net.faces[f].loop;
  const int n = static_cast<int>(loop.size());
  const int other = loop[side] == w ? (side + n - 1) % n : (side + 1) % n;
  return topo.face_sides[f][other].edge;
}

struct KH {
  double k = 0, h = 0;
};
// a = k b + h c in the tangent plane; b is a unit vector orthogonal to c and to the normal, so
// after projecting a and c onto the plane the coefficients are plain projections.
KH solve(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& n) {
  const Vec3 ap = project(a, n), cp = project(c, n);
  return {glm::dot(ap, b), glm::dot(ap, cp) / glm::dot(cp, cp)};
}

}  // namespace

EdgeCrossTangents edge_cross_tangents(const Network& net, const NetworkTopology& topo,
                                      const std::vector<TangentPlane>& planes, int e) {
  EdgeCrossTangents out;
  const auto& uses = topo.edge_faces[e];
  if (uses.empty()) return out;
  const NetworkEdge& ed = net.edges[e];
  const std::array<Vec3, 4> p{net.vertices[ed.v[0]], ed.handles[0], ed.handles[1],
                              net.vertices[ed.v[1]]};
  const std::array<Vec3, 3> c{3.0 * (p[1] - p[0]), 3.0 * (p[2] - p[1]), 3.0 * (p[3] - p[2])};
  const Vec3 n0 = planes[ed.v[0]].normal, n1 = planes[ed.v[1]].normal;
  // The tangent planes guarantee c0, c2 are not normal to them, so these are well defined.
  const Vec3 b0 = glm::normalize(glm::cross(n0, c[0]));
  const Vec3 b3 = glm::normalize(glm::cross(n1, c[2]));
  if (!(glm::dot(b0, b3) > -1 + 1e-6))
    throw DataError("", "network.edges[" + std::to_string(e) + "]",
                    "the edge turns half a revolution between its end tangent planes, so no "
                    "cross-boundary direction interpolates them");
  const Vec3 b1 = (2.0 * b0 + b3) / 3.0, b2 = (b0 + 2.0 * b3) / 3.0;
  for (const EdgeUse& use : uses) {
    const Vec3 a0 =
        end_tangent(net, neighbour_edge(net, topo, use.face, use.side, ed.v[0]), ed.v[0]);
    const Vec3 a3 =
        end_tangent(net, neighbour_edge(net, topo, use.face, use.side, ed.v[1]), ed.v[1]);
    const KH s = solve(a0, b0, c[0], n0), t = solve(a3, b3, c[2], n1);
    const double k0 = s.k, h0 = s.h, k1 = t.k, h1 = t.h;
    std::array<Vec3, 4> a;
    a[0] = a0;
    a[1] = (k1 - k0) * b0 / 3.0 + k0 * b1 + 2 * h0 * c[1] / 3.0 + h1 * c[0] / 3.0;
    a[2] = k1 * b2 - (k1 - k0) * b3 / 3.0 + h0 * c[2] / 3.0 + 2 * h1 * c[1] / 3.0;
    a[3] = a3;
    out.fields.push_back(a);
  }
  return out;
}

}  // namespace pl
