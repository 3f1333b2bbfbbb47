#include "core/network/sample_networks.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>

namespace pl {

NetworkEdge sphere_edge(const std::vector<Vec3>& vertices, int a, int b) {
  const Vec3 p = vertices.at(a), q = vertices.at(b);
  const double angle = std::acos(std::clamp(glm::dot(p, q), -1.0, 1.0));
  const double len = 4.0 / 3.0 * std::tan(angle / 4);
  const Vec3 ta = glm::normalize(q - glm::dot(q, p) * p);
  const Vec3 tb = glm::normalize(p - glm::dot(p, q) * q);
  return {{a, b}, {p + len * ta, q + len * tb}, ""};
}

Network cube_sphere_network(int k, FaceScheme scheme) {
  if (k < 1) throw std::invalid_argument("cube_sphere_network: k must be at least 1");
  Network net;
  // Grid points in integer cube coordinates (2i - k for i = 0..k), so points shared by cube
  // sides are found exactly.
  std::map<std::array<int, 3>, int> vertex_of;
  EdgeIndex edge_of;
  const auto vertex = [&](const std::array<int, 3>& c) {
    const auto [it, added] = vertex_of.emplace(c, int(net.vertices.size()));
    if (added) net.vertices.push_back(glm::normalize(Vec3(c[0], c[1], c[2])));
    return it->second;
  };
  const auto edge = [&](int a, int b) {
    const int e = int(net.edges.size());
    if (edge_of.add(a, b, e) == e) net.edges.push_back(sphere_edge(net.vertices, a, b));
  };
  // Each cube side: its outward axis and two in-plane axes with a x b = outward.
  struct Side {
    const char* name;
    int axis, sign, a, b;
  };
  const std::array<Side, 6> sides{{{"x+", 0, 1, 1, 2},
                                   {"x-", 0, -1, 2, 1},
                                   {"y+", 1, 1, 2, 0},
                                   {"y-", 1, -1, 0, 2},
                                   {"z+", 2, 1, 0, 1},
                                   {"z-", 2, -1, 1, 0}}};
  for (const Side& s : sides) {
    const auto at = [&](int i, int j) {
      std::array<int, 3> c{};
      c[s.axis] = s.sign * k;
      c[s.a] = 2 * i - k;
      c[s.b] = 2 * j - k;
      return vertex(c);
    };
    for (int i = 0; i < k; ++i)
      for (int j = 0; j < k; ++j) {
        const std::vector<int> loop{at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)};
        for (int m = 0; m < 4; ++m) edge(loop[m], loop[(m + 1) % 4]);
        net.faces.push_back(
            {loop, scheme,
             std::string(s.name) + "." + std::to_string(i) + "." + std::to_string(j)});
      }
  }
  return net;
}

}  // namespace pl
