// Scenes the benchmarks share: one n-sided network face on a wavy circle, its cubic edges
// straight-ish and lifted a little (the GB face, interior and network-face benchmarks).
#pragma once

#include <cmath>

#include "core/scene/scene.hpp"

namespace pl::bench {

// Vertices on the unit circle at height wave * sin(frequency * angle), each edge's handles at
// its thirds raised by lift; the face's scheme, degree and offsets are the caller's to set.
inline Scene wavy_ring_face(int n, double wave, int frequency, double lift) {
  Network net;
  NetworkFace face;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * M_PI * i / n;
    net.vertices.push_back({std::cos(a), std::sin(a), wave * std::sin(frequency * a)});
    face.loop.push_back(i);
  }
  for (int i = 0; i < n; ++i) {
    const Vec3 p = net.vertices[i], q = net.vertices[(i + 1) % n], up(0, 0, lift);
    NetworkEdge e;
    e.v = {i, (i + 1) % n};
    e.handles = {p + (q - p) / 3.0 + up, p + 2.0 * (q - p) / 3.0 + up};
    net.edges.push_back(e);
  }
  net.faces.push_back(face);
  Scene scene;
  scene.network = net;
  return scene;
}

}  // namespace pl::bench
