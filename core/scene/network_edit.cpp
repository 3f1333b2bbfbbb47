#include "core/scene/network_edit.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <tuple>

namespace pl {

namespace {

std::string str(int i) {
  return std::to_string(i);
}

void check_vertex(const Network& n, int v) {
  if (v < 0 || v >= int(n.vertices.size()))
    throw EditRefused("vertex " + str(v) + " does not exist (" + str(int(n.vertices.size())) +
                      " vertices)");
}
void check_edge(const Network& n, int e) {
  if (e < 0 || e >= int(n.edges.size()))
    throw EditRefused("edge " + str(e) + " does not exist (" + str(int(n.edges.size())) +
                      " edges)");
}
void check_face(const Network& n, int f) {
  if (f < 0 || f >= int(n.faces.size()))
    throw EditRefused("face " + str(f) + " does not exist (" + str(int(n.faces.size())) +
                      " faces)");
}

std::pair<int, int> key(int a, int b) {
  return std::minmax(a, b);
}

// The vertices a face side runs from and to (the direction the face runs its edge).
int use_from(const Network& n, const EdgeUse& u) {
  return n.faces[u.face].loop[u.side];
}
int use_to(const Network& n, const EdgeUse& u) {
  const auto& loop = n.faces[u.face].loop;
  return loop[(u.side + 1) % loop.size()];
}

Vec3 newell_normal(const Network& n, std::span<const int> loop) {
  Vec3 s(0);
  for (std::size_t i = 0; i < loop.size(); ++i)
    s += glm::cross(n.vertices[loop[i]], n.vertices[loop[(i + 1) % loop.size()]]);
  return s;
}

std::vector<int> reversed_loop(const std::vector<int>& loop) {
  std::vector<int> r{loop[0]};
  r.insert(r.end(), loop.rbegin(), loop.rend() - 1);
  return r;
}

}  // namespace

int add_vertex(Network& n, const Vec3& p) {
  if (!finite(p)) throw EditRefused("a vertex position must be finite");
  n.vertices.push_back(p);
  if (!n.normals.empty()) n.normals.emplace_back();
  return int(n.vertices.size()) - 1;
}

// One lookup: a scan of the edges costs less than building an EdgeIndex.
int edge_between(const Network& n, int a, int b) {
  for (std::size_t e = 0; e < n.edges.size(); ++e)
    if (key(n.edges[e].v[0], n.edges[e].v[1]) == key(a, b)) return int(e);
  return -1;
}

int add_edge(Network& n, int a, int b, const std::array<Vec3, 2>& handles) {
  check_vertex(n, a);
  check_vertex(n, b);
  if (a == b)
    throw EditRefused("an edge must join two different vertices (both are " + str(a) + ")");
  if (const int e = edge_between(n, a, b); e >= 0)
    throw EditRefused("vertices " + str(a) + " and " + str(b) + " are already joined by edge " +
                      str(e));
  for (const Vec3& h : handles)
    if (!finite(h)) throw EditRefused("edge handles must be finite");
  n.edges.push_back({{a, b}, handles, ""});
  return int(n.edges.size()) - 1;
}

std::vector<int> loop_of_edges(const Network& n, std::span<const int> edges) {
  if (edges.size() < 3)
    throw EditRefused("a face needs a closed chain of at least 3 edges, got " +
                      str(int(edges.size())));
  std::map<int, std::vector<int>> at;  // vertex -> chain edges at it
  std::set<int> seen;
  for (int e : edges) {
    check_edge(n, e);
    if (!seen.insert(e).second) throw EditRefused("edge " + str(e) + " is listed twice");
    for (int v : n.edges[e].v) at[v].push_back(e);
  }
  for (const auto& [v, es] : at)
    if (es.size() != 2)
      throw EditRefused("the edges do not form a closed chain: vertex " + str(v) + " is on " +
                        str(int(es.size())) + " of them");
  std::vector<int> loop;
  int e = edges[0], v = n.edges[e].v[0];
  do {
    loop.push_back(v);
    const int w = n.edges[e].v[0] == v ? n.edges[e].v[1] : n.edges[e].v[0];
    const auto& es = at[w];
    e = es[0] == e ? es[1] : es[0];
    v = w;
  } while (v != loop[0]);
  if (loop.size() != edges.size())
    throw EditRefused("the edges form several closed chains, not one (a chain of " +
                      str(int(loop.size())) + " of the " + str(int(edges.size())) + " edges)");
  return loop;
}

std::vector<std::array<int, 2>> missing_loop_edges(const Network& n, std::span<const int> loop) {
  const EdgeIndex by_ends(n);
  std::vector<std::array<int, 2>> out;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const int a = loop[i], b = loop[(i + 1) % loop.size()];
    if (a != b && by_ends.find(a, b) < 0) out.push_back({a, b});
  }
  return out;
}

std::vector<int> oriented_face_loop(const Network& n, std::vector<int> loop,
                                    std::optional<Vec3> towards) {
  const int sides = int(loop.size());
  if (sides < 3) throw EditRefused("a face needs at least 3 vertices, got " + str(sides));
  std::set<int> distinct;
  for (int v : loop) {
    check_vertex(n, v);
    if (!distinct.insert(v).second)
      throw EditRefused("vertex " + str(v) + " appears twice in the face's loop");
  }
  const EdgeIndex by_ends(n);
  std::vector<int> loop_edges;
  for (int i = 0; i < sides; ++i) {
    const int a = loop[i], b = loop[(i + 1) % sides];
    const int e = by_ends.find(a, b);
    if (e < 0)
      throw EditRefused("the loop is not closed by edges: no edge joins vertices " + str(a) +
                        " and " + str(b));
    loop_edges.push_back(e);
  }
  const auto uses = edge_uses(n, by_ends);
  for (std::size_t f = 0; f < n.faces.size(); ++f) {
    const auto& other = n.faces[f].loop;
    if (other.size() == loop.size() && std::set<int>(other.begin(), other.end()) == distinct)
      throw EditRefused("face " + str(int(f)) + " already has these vertices");
  }
  // Each neighbour says which way the new face must run its shared edge.
  int keep_from = -1, reverse_from = -1;  // a neighbour asking for each direction
  for (int i = 0; i < sides; ++i) {
    const int e = loop_edges[i];
    const auto& u = uses[e];
    if (u.size() >= 2)
      throw EditRefused("edge " + str(e) + " already joins faces " + str(u[0].face) + " and " +
                        str(u[1].face) + "; an edge can border at most two faces");
    if (u.size() == 1) (use_from(n, u[0]) == loop[i] ? reverse_from : keep_from) = u[0].face;
  }
  if (keep_from >= 0 && reverse_from >= 0)
    throw EditRefused("faces " + str(keep_from) + " and " + str(reverse_from) +
                      " run around the loop in opposite senses, so no direction of the new "
                      "face agrees with both");
  bool reverse = reverse_from >= 0;
  if (keep_from < 0 && reverse_from < 0 && towards)
    reverse = glm::dot(newell_normal(n, loop), *towards) < 0;
  return reverse ? reversed_loop(loop) : loop;
}

int add_face(Network& n, std::vector<int> loop, std::optional<Vec3> towards) {
  NetworkFace f;
  f.loop = oriented_face_loop(n, std::move(loop), towards);
  n.faces.push_back(std::move(f));
  return int(n.faces.size()) - 1;
}

std::vector<std::vector<int>> boundary_loops(const Network& n) {
  const auto uses = edge_uses(n, EdgeIndex(n));
  // The directed boundary edges a filling face runs: against the one face using the edge.
  std::map<int, std::vector<int>> next;  // vertex -> vertices a filling face may run to
  for (const auto& u : uses)
    if (u.size() == 1) next[use_to(n, u[0])].push_back(use_from(n, u[0]));
  std::set<std::pair<int, int>> used;
  std::vector<std::vector<int>> loops;
  for (const auto& [start, targets] : next) {
    for (int first : targets) {
      if (used.count({start, first})) continue;
      std::vector<int> loop{start};
      std::vector<std::pair<int, int>> steps{{start, first}};
      int v = first;
      bool simple = true;
      while (v != start) {
        const auto it = next.find(v);
        if (it == next.end() || it->second.size() != 1) {
          simple = false;  // an open boundary, or a vertex where boundary loops touch
          break;
        }
        loop.push_back(v);
        steps.emplace_back(v, it->second[0]);
        v = it->second[0];
        if (loop.size() > n.vertices.size()) {
          simple = false;
          break;
        }
      }
      for (const auto& s : steps) used.insert(s);
      if (simple && next.at(start).size() == 1) loops.push_back(std::move(loop));
    }
  }
  return loops;
}

std::vector<int> fill_holes(Network& n, int min_sides, int max_sides) {
  std::vector<int> added;
  for (std::vector<int>& loop : boundary_loops(n)) {
    const int sides = int(loop.size());
    if (sides < min_sides || sides > max_sides) continue;
    // The loop of a lone face is that face's boundary too: no second face on the same vertices.
    bool exists = false;
    const std::set<int> vs(loop.begin(), loop.end());
    for (const NetworkFace& f : n.faces)
      exists = exists ||
               (f.loop.size() == loop.size() && std::set<int>(f.loop.begin(), f.loop.end()) == vs);
    if (exists) continue;
    NetworkFace f;
    f.loop = std::move(loop);
    n.faces.push_back(std::move(f));
    added.push_back(int(n.faces.size()) - 1);
  }
  if (added.empty())
    throw EditRefused("no closed loop of boundary edges with " + str(min_sides) + " to " +
                      str(max_sides) + " sides to fill");
  return added;
}

Removed delete_elements(Network& n, std::span<const int> vertices, std::span<const int> edges,
                        std::span<const int> faces) {
  std::vector<bool> vdel(n.vertices.size()), edel(n.edges.size()), fdel(n.faces.size());
  for (int v : vertices) check_vertex(n, v), vdel[v] = true;
  for (int e : edges) check_edge(n, e), edel[e] = true;
  for (int f : faces) check_face(n, f), fdel[f] = true;
  for (std::size_t e = 0; e < n.edges.size(); ++e)
    if (vdel[n.edges[e].v[0]] || vdel[n.edges[e].v[1]]) edel[e] = true;
  const EdgeIndex by_ends(n);
  for (std::size_t f = 0; f < n.faces.size(); ++f) {
    const auto& loop = n.faces[f].loop;
    for (std::size_t i = 0; i < loop.size() && !fdel[f]; ++i) {
      const int e = by_ends.find(loop[i], loop[(i + 1) % loop.size()]);
      fdel[f] = vdel[loop[i]] || (e >= 0 && edel[e]);
    }
  }
  Removed removed;
  std::vector<int> vmap(n.vertices.size(), -1);
  Network out;
  for (std::size_t v = 0; v < n.vertices.size(); ++v) {
    if (vdel[v]) {
      removed.vertices.push_back(int(v));
      continue;
    }
    vmap[v] = int(out.vertices.size());
    out.vertices.push_back(n.vertices[v]);
    if (!n.normals.empty()) out.normals.push_back(n.normals[v]);
  }
  for (std::size_t e = 0; e < n.edges.size(); ++e) {
    if (edel[e]) {
      removed.edges.push_back(int(e));
      continue;
    }
    NetworkEdge ed = n.edges[e];
    for (int& v : ed.v) v = vmap[v];
    out.edges.push_back(std::move(ed));
  }
  for (std::size_t f = 0; f < n.faces.size(); ++f) {
    if (fdel[f]) {
      removed.faces.push_back(int(f));
      continue;
    }
    NetworkFace face = n.faces[f];
    for (int& v : face.loop) v = vmap[v];
    out.faces.push_back(std::move(face));
  }
  n = std::move(out);
  return removed;
}

Split split_edge(Network& n, int e, double t, std::optional<Vec3> normal) {
  check_edge(n, e);
  if (!(t > 0 && t < 1))
    throw EditRefused("an edge is split at a parameter between 0 and 1 (exclusive), got " +
                      std::to_string(t));
  const NetworkEdge ed = n.edges[e];
  const int a = ed.v[0], b = ed.v[1];
  std::vector<int> faces;
  const auto uses = edge_uses(n, EdgeIndex(n));
  for (const EdgeUse& u : uses[e]) faces.push_back(u.face);
  if (!faces.empty() && !normal)
    throw EditRefused("the new vertex of a split edge that borders a face needs a normal");
  if (normal && !(glm::length(*normal) > 0 && std::isfinite(glm::length(*normal))))
    throw EditRefused("the new vertex's normal must be a finite non-zero vector");
  // de Casteljau at t.
  const Vec3 p0 = n.vertices[a], p1 = ed.handles[0], p2 = ed.handles[1], p3 = n.vertices[b];
  const auto lerp = [t](const Vec3& x, const Vec3& y) { return (1 - t) * x + t * y; };
  const Vec3 p01 = lerp(p0, p1), p12 = lerp(p1, p2), p23 = lerp(p2, p3);
  const Vec3 p012 = lerp(p01, p12), p123 = lerp(p12, p23);
  const Vec3 m = lerp(p012, p123);
  Split s;
  s.vertex = int(n.vertices.size());
  n.vertices.push_back(m);
  if (normal || !n.normals.empty()) {
    n.normals.resize(n.vertices.size() - 1);
    n.normals.push_back(normal ? std::optional<Vec3>(stored_normal(*normal)) : std::nullopt);
  }
  n.edges[e].v = {a, s.vertex};
  n.edges[e].handles = {p01, p012};
  s.edge = int(n.edges.size());
  n.edges.push_back({{s.vertex, b}, {p123, p23}, ""});
  for (int f : faces) {
    auto& loop = n.faces[f].loop;
    for (std::size_t i = 0; i < loop.size(); ++i)
      if (key(loop[i], loop[(i + 1) % loop.size()]) == key(a, b)) {
        loop.insert(loop.begin() + (i + 1), s.vertex);
        break;
      }
    if (n.faces[f].scheme == FaceScheme::Gregory && loop.size() > 4)
      n.faces[f].scheme = FaceScheme::Auto;
  }
  s.faces = std::move(faces);
  return s;
}

void set_face_scheme(Network& n, int f, FaceScheme scheme) {
  check_face(n, f);
  const int sides = int(n.faces[f].loop.size());
  if (scheme == FaceScheme::Gregory && sides != 3 && sides != 4)
    throw EditRefused("face " + str(f) + " has " + str(sides) +
                      " sides: a Gregory patch has 3 or 4 (use Auto or GB)");
  n.faces[f].scheme = scheme;
}

void set_face_name(Network& n, int f, std::string name) {
  check_face(n, f);
  n.faces[f].name = std::move(name);
}

void set_edge_name(Network& n, int e, std::string name) {
  check_edge(n, e);
  n.edges[e].name = std::move(name);
}

void set_vertex_normal(Network& n, int v, std::optional<Vec3> normal) {
  check_vertex(n, v);
  if (normal) {
    const double len = glm::length(*normal);
    if (!(len > 0) || !std::isfinite(len))
      throw EditRefused("a vertex normal must be a finite non-zero vector");
    normal = stored_normal(*normal);
  }
  if (n.normals.empty()) {
    if (!normal) return;
    n.normals.resize(n.vertices.size());
  }
  n.normals[v] = normal;
  // No fixed normal left: the file needs no normals array.
  if (std::none_of(n.normals.begin(), n.normals.end(), [](const auto& x) { return x.has_value(); }))
    n.normals.clear();
}

Vec3 stored_normal(const Vec3& normal) {
  // Normalising again changes a unit vector in its last bits at most, and soon no more: either a
  // fixed point, or a short cycle of vectors that normalise into each other. Of a cycle the
  // smallest (lexicographically) is taken, so that the result is the same from every vector of
  // the cycle: the reader (which calls this too) maps a stored normal to itself.
  constexpr int kMostSteps = 16;
  std::array<Vec3, kMostSteps + 1> seen;  // on the stack: the reader calls this per normal
  int count = 0;
  Vec3 n = glm::normalize(normal);
  seen[count++] = n;
  for (int i = 0; i < kMostSteps; ++i) {
    const Vec3 again = glm::normalize(n);
    if (again == n) return n;
    const auto end = seen.begin() + count;
    const auto cycle = std::find(seen.begin(), end, again);
    if (cycle != end)
      return *std::min_element(cycle, end, [](const Vec3& a, const Vec3& b) {
        return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z);
      });
    seen[count++] = again;
    n = again;
  }
  return n;
}

namespace {
using transfinite::RibbonScheme;
// The keywords of the patch schemes; the ribbon schemes are named by their own module
// (transfinite::ribbon_scheme_name), so each name is written once.
struct SchemeName {
  FaceScheme scheme;
  const char* keyword;
};
constexpr SchemeName kSchemeNames[] = {
    {FaceScheme::Auto, "auto"}, {FaceScheme::Gregory, "gregory"}, {FaceScheme::GB, "gb"}};
struct RibbonName {
  FaceScheme scheme;
  RibbonScheme ribbon;
};
constexpr RibbonName kRibbonSchemes[] = {
    {FaceScheme::SideBased, RibbonScheme::SideBased},
    {FaceScheme::CornerBased, RibbonScheme::CornerBased},
    {FaceScheme::GeneralizedCoons, RibbonScheme::GeneralizedCoons},
    {FaceScheme::CompositeRibbon, RibbonScheme::CompositeRibbon},
    {FaceScheme::Midpoint, RibbonScheme::Midpoint},
    {FaceScheme::MidpointCoons, RibbonScheme::MidpointCoons},
    {FaceScheme::Elastic, RibbonScheme::Elastic},
};
constexpr FaceScheme kAllFaceSchemes[] = {
    FaceScheme::Gregory,          FaceScheme::GB,
    FaceScheme::SideBased,        FaceScheme::CornerBased,
    FaceScheme::GeneralizedCoons, FaceScheme::CompositeRibbon,
    FaceScheme::Midpoint,         FaceScheme::MidpointCoons,
    FaceScheme::Elastic,
};
}  // namespace

std::string scheme_keyword(FaceScheme s) {
  for (const SchemeName& n : kSchemeNames)
    if (n.scheme == s) return n.keyword;
  if (const auto r = ribbon_scheme_of(s)) return std::string(transfinite::ribbon_scheme_name(*r));
  return "?";
}

std::optional<FaceScheme> parse_scheme_keyword(std::string_view keyword) {
  for (const SchemeName& n : kSchemeNames)
    if (keyword == n.keyword) return n.scheme;
  if (const auto r = transfinite::parse_ribbon_scheme(keyword))
    for (const RibbonName& n : kRibbonSchemes)
      if (n.ribbon == *r) return n.scheme;
  return std::nullopt;
}

std::span<const FaceScheme> all_face_schemes() {
  return kAllFaceSchemes;
}

std::string face_scheme_keywords() {
  std::string out;
  for (FaceScheme s : all_face_schemes()) out += (out.empty() ? "" : ", ") + scheme_keyword(s);
  return out;
}

bool is_ribbon_scheme(FaceScheme s) {
  return ribbon_scheme_of(s).has_value();
}

std::optional<RibbonScheme> ribbon_scheme_of(FaceScheme s) {
  for (const RibbonName& n : kRibbonSchemes)
    if (n.scheme == s) return n.ribbon;
  return std::nullopt;
}

}  // namespace pl
