// Scenes with many-sided GB faces for the CAD export's tests and benchmark: a regular n-gon cap of
// the unit sphere (a smooth bulge over a regular polygon, its corners at `latitude_deg`), alone or
// with a ring of n quads below it down to the mirrored latitude (a network whose n-gon shares
// every edge with a neighbour). Edges are the sphere's cubic arcs (sphere_edge), so every end
// tangent lies in the sphere's tangent plane and a G1 filling exists.
#pragma once

#include <cmath>
#include <string>

#include "core/network/sample_networks.hpp"
#include "core/scene/scene.hpp"

namespace pl::test {

inline Scene ngon_cap_scene(int n, bool with_ring, double latitude_deg = 30) {
  const auto at = [](double lat_deg, double lon) {
    const double f = lat_deg * M_PI / 180;
    return Vec3(std::cos(f) * std::cos(lon), std::cos(f) * std::sin(lon), std::sin(f));
  };
  Network net;
  for (int i = 0; i < n; ++i) net.vertices.push_back(at(latitude_deg, 2 * M_PI * i / n));
  if (with_ring)
    for (int i = 0; i < n; ++i) net.vertices.push_back(at(-latitude_deg, 2 * M_PI * i / n));
  NetworkFace cap;
  for (int i = 0; i < n; ++i) {
    net.edges.push_back(sphere_edge(net.vertices, i, (i + 1) % n));
    cap.loop.push_back(i);
  }
  cap.scheme = FaceScheme::GB;
  cap.name = "cap";
  net.faces.push_back(cap);
  if (with_ring) {
    for (int i = 0; i < n; ++i) {
      net.edges.push_back(sphere_edge(net.vertices, n + i, i));                // upwards
      net.edges.push_back(sphere_edge(net.vertices, n + i, n + (i + 1) % n));  // bottom ring
    }
    for (int i = 0; i < n; ++i) {
      const int j = (i + 1) % n;
      NetworkFace q;
      q.loop = {i, n + i, n + j, j};  // outwards, as the cap (counter-clockwise seen from above)
      q.scheme = FaceScheme::Auto;
      q.name = "ring" + std::to_string(i);
      net.faces.push_back(q);
    }
  }
  Scene scene;
  scene.name = std::to_string(n) + "-gon cap";
  scene.network = net;
  return scene;
}

}  // namespace pl::test
