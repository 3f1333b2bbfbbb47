#include "app/editor/logic/grid_scene.hpp"

#include <cmath>

namespace pl {

Scene make_grid_network_scene(int rows, int cols) {
  Scene s;
  s.name = "drag benchmark grid";
  Network net;
  auto height = [&](double x, double y) {
    const double u = x / cols - 0.5, v = y / rows - 0.5;
    return 0.4 * std::exp(-6 * (u * u + v * v));
  };
  auto at = [&](double x, double y) { return Vec3(x, y, height(x, y)); };
  auto vid = [&](int i, int j) { return i * (cols + 1) + j; };
  for (int i = 0; i <= rows; ++i)
    for (int j = 0; j <= cols; ++j) net.vertices.push_back(at(j, i));
  auto edge = [&](int a, int b) {
    NetworkEdge e;
    e.v = {a, b};
    const Vec3 pa = net.vertices[a], pb = net.vertices[b];
    // Handles at thirds, lifted onto the height field so the edges are curved.
    const Vec3 h1 = pa + (pb - pa) / 3.0, h2 = pa + 2.0 * (pb - pa) / 3.0;
    e.handles = {at(h1.x, h1.y), at(h2.x, h2.y)};
    net.edges.push_back(e);
  };
  for (int i = 0; i <= rows; ++i)
    for (int j = 0; j < cols; ++j) edge(vid(i, j), vid(i, j + 1));
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j <= cols; ++j) edge(vid(i, j), vid(i + 1, j));
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < cols; ++j) {
      NetworkFace f;
      f.loop = {vid(i, j), vid(i, j + 1), vid(i + 1, j + 1), vid(i + 1, j)};  // counter-clockwise
      f.name = "face" + std::to_string(i * cols + j);
      net.faces.push_back(f);
    }
  s.network = std::move(net);
  return s;
}

}  // namespace pl
