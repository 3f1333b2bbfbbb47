#include "core/scene/network.hpp"

#include <algorithm>
#include <set>

#include "core/base/data_error.hpp"

namespace pl {

BezierCurve Network::edge_curve(int e) const {
  const NetworkEdge& ed = edges.at(e);
  return BezierCurve({vertices.at(ed.v[0]), ed.handles[0], ed.handles[1], vertices.at(ed.v[1])});
}

EdgeIndex::EdgeIndex(const Network& net) {
  for (std::size_t e = 0; e < net.edges.size(); ++e)
    add(net.edges[e].v[0], net.edges[e].v[1], static_cast<int>(e));
}

int EdgeIndex::add(int a, int b, int e) {
  return by_ends_.emplace(std::minmax(a, b), e).first->second;
}

int EdgeIndex::find(int a, int b) const {
  const auto it = by_ends_.find(std::minmax(a, b));
  return it == by_ends_.end() ? -1 : it->second;
}

std::vector<std::vector<EdgeUse>> edge_uses(const Network& net, const EdgeIndex& index) {
  std::vector<std::vector<EdgeUse>> uses(net.edges.size());
  for (std::size_t f = 0; f < net.faces.size(); ++f) {
    const auto& loop = net.faces[f].loop;
    for (std::size_t i = 0; i < loop.size(); ++i)
      if (const int e = index.find(loop[i], loop[(i + 1) % loop.size()]); e >= 0)
        uses[e].push_back({static_cast<int>(f), static_cast<int>(i)});
  }
  return uses;
}

NetworkTopology validate_network(const Network& net, const std::string& source) {
  const auto fail = [&](const std::string& path, const std::string& msg) {
    throw DataError(source, "network." + path, msg);
  };
  const int nv = static_cast<int>(net.vertices.size());
  if (!net.normals.empty() && net.normals.size() != net.vertices.size())
    fail("normals", "has " + std::to_string(net.normals.size()) + " entries for " +
                        std::to_string(nv) + " vertices");
  NetworkTopology topo;
  topo.vertex_edges.resize(nv);
  topo.edge_faces.resize(net.edges.size());
  EdgeIndex edge_of;
  for (std::size_t e = 0; e < net.edges.size(); ++e) {
    const auto& ed = net.edges[e];
    const std::string path = "edges[" + std::to_string(e) + "].v";
    for (int k = 0; k < 2; ++k)
      if (ed.v[k] < 0 || ed.v[k] >= nv)
        fail(path + "[" + std::to_string(k) + "]", "vertex " + std::to_string(ed.v[k]) +
                                                       " does not exist (" + std::to_string(nv) +
                                                       " vertices)");
    if (ed.v[0] == ed.v[1]) fail(path, "an edge must join two different vertices");
    if (const int other = edge_of.add(ed.v[0], ed.v[1], static_cast<int>(e));
        other != static_cast<int>(e)) {
      const auto key = std::minmax(ed.v[0], ed.v[1]);
      fail(path, "vertices " + std::to_string(key.first) + " and " + std::to_string(key.second) +
                     " are already joined by edge " + std::to_string(other));
    }
    topo.vertex_edges[ed.v[0]].push_back(static_cast<int>(e));
    topo.vertex_edges[ed.v[1]].push_back(static_cast<int>(e));
  }
  for (std::size_t f = 0; f < net.faces.size(); ++f) {
    const auto& loop = net.faces[f].loop;
    const std::string path = "faces[" + std::to_string(f) + "].loop";
    const int n = static_cast<int>(loop.size());
    if (n < 3) fail(path, "a face needs at least 3 vertices, got " + std::to_string(n));
    std::set<int> seen;
    for (int i = 0; i < n; ++i) {
      const std::string ipath = path + "[" + std::to_string(i) + "]";
      if (loop[i] < 0 || loop[i] >= nv)
        fail(ipath, "vertex " + std::to_string(loop[i]) + " does not exist (" + std::to_string(nv) +
                        " vertices)");
      if (!seen.insert(loop[i]).second)
        fail(ipath, "vertex " + std::to_string(loop[i]) + " appears twice in the loop");
    }
    std::vector<FaceSide> sides(n);
    for (int i = 0; i < n; ++i) {
      const int a = loop[i], b = loop[(i + 1) % n];
      const int e = edge_of.find(a, b);
      if (e < 0)
        fail(path + "[" + std::to_string(i) + "]",
             "no edge joins vertices " + std::to_string(a) + " and " + std::to_string(b));
      sides[i] = {e, net.edges[e].v[0] != a};
      auto& uses = topo.edge_faces[e];
      if (uses.size() == 2)
        fail(path + "[" + std::to_string(i) + "]",
             "edge " + std::to_string(e) + " is already used by faces " +
                 std::to_string(uses[0].face) + " and " + std::to_string(uses[1].face));
      if (uses.size() == 1) {
        const FaceSide& other = topo.face_sides[uses[0].face][uses[0].side];
        if (other.reversed == sides[i].reversed)
          fail(path + "[" + std::to_string(i) + "]",
               "edge " + std::to_string(e) + " is traversed in the same direction by face " +
                   std::to_string(uses[0].face) +
                   "; faces sharing an edge must traverse it in opposite directions");
      }
      uses.push_back({static_cast<int>(f), i});
    }
    topo.face_sides.push_back(std::move(sides));
  }
  return topo;
}

FaceScheme resolve_scheme(const NetworkFace& face, std::optional<FaceScheme> override_scheme) {
  const int n = static_cast<int>(face.loop.size());
  const bool gregory_allowed = n == 3 || n == 4;
  FaceScheme s = override_scheme.value_or(face.scheme);
  if (override_scheme && *override_scheme == FaceScheme::Gregory && !gregory_allowed)
    s = face.scheme;  // the CLI spec: other faces keep gb
  if (s == FaceScheme::Auto) s = gregory_allowed ? FaceScheme::Gregory : FaceScheme::GB;
  if (s == FaceScheme::Gregory && !gregory_allowed) s = FaceScheme::GB;
  return s;
}

bool is_free_interior_point(int d, const InteriorOffset& at) {
  if (at.centre) return true;
  return at.layer >= 2 && at.layer < gb_face_layers(d) && at.j >= 2 && d - at.j >= 2;
}

std::string interior_offset_problem(int n, int d, const InteriorOffset& at) {
  if (at.centre) return "";
  std::string name = "[";
  name += std::to_string(at.side);
  name += ", ";
  name += std::to_string(at.j);
  name += ", ";
  name += std::to_string(at.layer);
  name += "]";
  if (at.side < 0 || at.side >= n)
    return "point " + name + ": side " + std::to_string(at.side) + " does not exist (" +
           std::to_string(n) + " sides)";
  if (at.layer < 0 || at.layer >= gb_face_layers(d))
    return "point " + name + ": layer " + std::to_string(at.layer) + " does not exist (degree " +
           std::to_string(d) + " has layers 0.." + std::to_string(gb_face_layers(d) - 1) + ")";
  if (at.j < 0 || at.j > d) return "point " + name + ": j must be in 0.." + std::to_string(d);
  if (!is_free_interior_point(d, at))
    return "point " + name +
           " is not free: layers 0 and 1 are the G1 boundary data (free points: layers k >= 2 with "
           "2 <= j <= d - 2, and \"center\")";
  return "";
}

}  // namespace pl
