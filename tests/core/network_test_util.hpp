// Test networks and the measurements of the network tests: boundary deviation from the edges
// and the angle between neighbouring faces' normals, both from exact patch derivatives.
#pragma once

#include <cmath>
#include <vector>

#include "core/network/network_filling.hpp"
#include "core/network/sample_networks.hpp"
#include "core/scene/network.hpp"

namespace pl::test {

inline Vec3 on_sphere(double latitude_deg, double longitude_deg) {
  const double f = latitude_deg * M_PI / 180, l = longitude_deg * M_PI / 180;
  return {std::cos(f) * std::cos(l), std::cos(f) * std::sin(l), std::sin(f)};
}

// A blob on the unit sphere: pentagonal pyramid on top (apex valence 5), a ring of five quads,
// closed at the bottom by a triangle and a quad (valences 3 and 4). 10 + 5... faces:
// 5 triangles, 5 quads, 1 triangle, 1 quad. Without `closed`, the bottom two faces and their
// diagonal are left out and the bottom ring is the boundary.
inline Network sphere_blob(bool closed) {
  Network n;
  n.vertices.push_back({0, 0, 1});                                                // 0: apex
  for (int i = 0; i < 5; ++i) n.vertices.push_back(on_sphere(25, 72 * i + 10));   // 1..5
  for (int i = 0; i < 5; ++i) n.vertices.push_back(on_sphere(-35, 72 * i + 10));  // 6..10
  const auto T = [](int i) { return 1 + (i % 5); };
  const auto B = [](int i) { return 6 + (i % 5); };
  for (int i = 0; i < 5; ++i) {
    n.edges.push_back(sphere_edge(n.vertices, 0, T(i)));
    n.edges.push_back(sphere_edge(n.vertices, T(i), T(i + 1)));
    n.edges.push_back(sphere_edge(n.vertices, B(i), T(i)));  // runs upwards
    n.edges.push_back(sphere_edge(n.vertices, B(i), B(i + 1)));
  }
  for (int i = 0; i < 5; ++i) {
    n.faces.push_back({{0, T(i), T(i + 1)}, FaceScheme::Auto, ""});
    n.faces.push_back({{T(i), B(i), B(i + 1), T(i + 1)}, FaceScheme::Auto, ""});
  }
  if (closed) {
    n.edges.push_back(sphere_edge(n.vertices, B(2), B(0)));
    n.faces.push_back({{B(0), B(2), B(1)}, FaceScheme::Auto, "bottom-tri"});
    n.faces.push_back({{B(0), B(4), B(3), B(2)}, FaceScheme::Auto, "bottom-quad"});
  }
  return n;
}

// The same network under a linear map (an ellipsoid blob): tangent planes map to tangent
// planes, so it stays G1-fillable, but nothing is spherical any more.
inline Network mapped(Network n, const glm::dmat3& m) {
  for (Vec3& v : n.vertices) v = m * v;
  for (NetworkEdge& e : n.edges)
    for (Vec3& h : e.handles) h = m * h;
  return n;
}

// An open height-field network z = f(x, y) on a 3x3 grid: three quads and two triangles whose
// diagonal makes the centre vertex valence 5. Handles lie in the graph's tangent planes; the
// exact normals are given at every other vertex (the rest are fitted).
inline double height(double x, double y) {
  return 0.3 * std::sin(x) * std::cos(y) + 0.1 * x * y;
}
inline Vec3 height_gradient(double x, double y) {  // (f_x, f_y, 0)
  return {0.3 * std::cos(x) * std::cos(y) + 0.1 * y, -0.3 * std::sin(x) * std::sin(y) + 0.1 * x, 0};
}
inline Network height_field() {
  Network n;
  const auto id = [](int i, int j) { return j * 3 + i; };
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) n.vertices.push_back({i, j, height(i, j)});
  const auto tangent = [&](int v, Vec3 d) {  // d in the xy plane
    const Vec3 p = n.vertices[v], g = height_gradient(p.x, p.y);
    return Vec3(d.x, d.y, g.x * d.x + g.y * d.y);
  };
  const auto edge = [&](int a, int b) {
    const Vec3 d = n.vertices[b] - n.vertices[a];
    const Vec3 dxy(d.x, d.y, 0);
    n.edges.push_back(
        {{a, b},
         {n.vertices[a] + tangent(a, dxy) / 3.0, n.vertices[b] - tangent(b, dxy) / 3.0},
         ""});
  };
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 2; ++i) edge(id(i, j), id(i + 1, j));
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 3; ++i) edge(id(i, j), id(i, j + 1));
  edge(id(1, 1), id(2, 2));
  n.faces.push_back({{id(0, 0), id(1, 0), id(1, 1), id(0, 1)}, FaceScheme::Auto, ""});
  n.faces.push_back({{id(1, 0), id(2, 0), id(2, 1), id(1, 1)}, FaceScheme::Auto, ""});
  n.faces.push_back({{id(0, 1), id(1, 1), id(1, 2), id(0, 2)}, FaceScheme::Auto, ""});
  n.faces.push_back({{id(1, 1), id(2, 1), id(2, 2)}, FaceScheme::Auto, ""});
  n.faces.push_back({{id(1, 1), id(2, 2), id(1, 2)}, FaceScheme::Auto, ""});
  for (std::size_t v = 0; v < n.vertices.size(); ++v) {
    const Vec3 g = height_gradient(n.vertices[v].x, n.vertices[v].y);
    if (v % 2 == 0)
      n.normals.push_back(glm::normalize(Vec3(-g.x, -g.y, 1)));
    else
      n.normals.push_back(std::nullopt);
  }
  return n;
}

// Size of the network: the diagonal of its control points' bounding box.
inline double network_size(const Network& n) {
  Vec3 lo(1e300), hi(-1e300);
  const auto add = [&](const Vec3& p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  };
  for (const Vec3& p : n.vertices) add(p);
  for (const NetworkEdge& e : n.edges)
    for (const Vec3& h : e.handles) add(h);
  return glm::length(hi - lo);
}

struct FaceSurface {  // what the measurements need of a filled face
  const Patch* patch;
  const std::vector<int>* patch_side;
};

inline Vec3 unit_normal(const Patch& p, Vec2 x) {
  const SurfaceJet j = p.evaluate(x);
  return glm::normalize(glm::cross(j.su, j.sv));
}

// Domain point of face side `side` at edge parameter t (t runs along the edge itself).
inline Vec2 side_point(const FaceSurface& f, const NetworkTopology& topo, int face, int side,
                       double t) {
  const double tau = topo.face_sides[face][side].reversed ? 1 - t : t;
  return f.patch->domain().side_point(f.patch_side->at(side), tau);
}

constexpr int kEdgeSamples = 64;

// Largest distance between a face's boundary and the network edges, over all faces.
inline double max_boundary_deviation(const Network& n, const NetworkTopology& topo,
                                     const std::vector<FaceSurface>& faces) {
  double dev = 0;
  for (std::size_t f = 0; f < faces.size(); ++f)
    for (std::size_t i = 0; i < topo.face_sides[f].size(); ++i) {
      const BezierCurve c = n.edge_curve(topo.face_sides[f][i].edge);
      for (int k = 0; k <= kEdgeSamples; ++k) {
        const double t = double(k) / kEdgeSamples;
        const Vec2 x = side_point(faces[f], topo, int(f), int(i), t);
        dev = std::max(dev, glm::length(faces[f].patch->evaluate(x).p - c.point(t)));
      }
    }
  return dev;
}

inline double angle_between_deg(const Vec3& a, const Vec3& b) {
  return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b)) * 180 / M_PI;
}

// The unit normal of face `face` at parameter t of its side `side`. Where the parameterisation
// is singular (Su x Sv = 0: a corner whose two sides run on in one direction, as at a split
// edge's vertex) it is the limit along the side, extrapolated from t -+ h and t -+ 2h
// (Richardson, error O(h^2)).
inline Vec3 side_normal(const FaceSurface& f, const NetworkTopology& topo, int face, int side,
                        double t) {
  const auto raw = [&](double s) {
    const SurfaceJet j = f.patch->evaluate(side_point(f, topo, face, side, s));
    return std::pair{glm::cross(j.su, j.sv), glm::length(j.su) * glm::length(j.sv)};
  };
  const auto [n, scale] = raw(t);
  if (glm::length(n) > 1e-12 * scale) return glm::normalize(n);
  const double h = t < 0.5 ? 1e-5 : -1e-5;
  return glm::normalize(2.0 * glm::normalize(raw(t + h).first) -
                        glm::normalize(raw(t + 2 * h).first));
}

// Largest angle between the two faces' normals along every shared edge, end vertices included.
inline double max_g1_angle_deg(const NetworkTopology& topo, const std::vector<FaceSurface>& faces) {
  double worst = 0;
  for (const auto& uses : topo.edge_faces) {
    if (uses.size() != 2) continue;
    for (int k = 0; k <= kEdgeSamples; ++k) {
      const double t = double(k) / kEdgeSamples;
      Vec3 nrm[2];
      for (int s = 0; s < 2; ++s)
        nrm[s] = side_normal(faces[uses[s].face], topo, uses[s].face, uses[s].side, t);
      worst = std::max(worst, angle_between_deg(nrm[0], nrm[1]));
    }
  }
  return worst;
}

inline std::vector<FaceSurface> surfaces(const NetworkFilling& filling) {
  std::vector<FaceSurface> out;
  for (const FacePatch& fp : filling.faces) out.push_back({fp.patch.get(), &fp.patch_side});
  return out;
}

// The largest G1 angle over the shared edges of a from-scratch filling of n (exact derivatives,
// not an engine's samples) and how many vertices it had to project.
struct Continuity {
  double angle_deg = 0;
  std::size_t projected = 0;
};
inline Continuity filled_continuity(const Network& n) {
  const NetworkTopology topo = validate_network(n, "test");
  const NetworkFilling filling = fill_network(n, topo, std::nullopt, "test");
  return {max_g1_angle_deg(topo, surfaces(filling)), filling.projected_vertices.size()};
}

}  // namespace pl::test
