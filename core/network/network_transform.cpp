#include "core/network/network_transform.hpp"

#include <string>
#include <vector>

#include "core/network/handle_planes.hpp"
#include "core/scene/network_edit.hpp"

namespace pl {

void transform_network(Network& network, std::span<const int> vertices,
                       std::span<const std::array<int, 2>> handles, const Similarity& t) {
  if (!t.valid()) throw EditRefused("not a rotation, scale or move (non-finite or degenerate)");
  const int nv = static_cast<int>(network.vertices.size());
  const int ne = static_cast<int>(network.edges.size());
  std::vector<char> moving(nv, 0);
  for (int v : vertices) {
    if (v < 0 || v >= nv) throw EditRefused("no vertex " + std::to_string(v));
    moving[v] = 1;
  }
  for (const auto& [e, end] : handles)
    if (e < 0 || e >= ne || end < 0 || end > 1)
      throw EditRefused("no handle " + std::to_string(end) + " of edge " + std::to_string(e));

  // Everything read before anything is written: the transform of the old network.
  for (NetworkEdge& edge : network.edges)
    for (int end = 0; end < 2; ++end)
      if (moving[edge.v[end]]) edge.handles[end] = t.point(edge.handles[end]);
  for (int v = 0; v < nv; ++v) {
    if (!moving[v]) continue;
    network.vertices[v] = t.point(network.vertices[v]);
    if (v < static_cast<int>(network.normals.size()) && network.normals[v])
      network.normals[v] = stored_normal(t.direction(*network.normals[v]));
  }
  // Handles named on their own, at vertices that stay: moved, then kept in their vertex's plane
  // (the other named handles at that vertex do not hold the plane, as in a drag of several).
  for (const auto& [e, end] : handles) {
    const int v = network.edges[e].v[end];
    if (moving[v]) continue;
    std::vector<int> others;
    for (const auto& [f, f_end] : handles)
      if ((f != e || f_end != end) && network.edges[f].v[f_end] == v) others.push_back(f);
    network.edges[e].handles[end] =
        constrained_handle(network, e, end, t.point(network.edges[e].handles[end]), others);
  }
}

}  // namespace pl
