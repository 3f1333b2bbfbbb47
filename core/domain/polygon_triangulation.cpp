#include "core/domain/polygon_triangulation.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

namespace pl {

namespace {

double orient(Vec2 a, Vec2 b, Vec2 c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// > 0 when d lies inside the circumcircle of the counter-clockwise triangle abc.
double incircle(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  const double adx = a.x - d.x, ady = a.y - d.y, bdx = b.x - d.x, bdy = b.y - d.y;
  const double cdx = c.x - d.x, cdy = c.y - d.y;
  const double ad = adx * adx + ady * ady, bd = bdx * bdx + bdy * bdy, cd = cdx * cdx + cdy * cdy;
  return adx * (bdy * cd - bd * cdy) - ady * (bdx * cd - bd * cdx) + ad * (bdx * cdy - bdy * cdx);
}

// Triangles (counter-clockwise) with their neighbours: nbr_[t][e] is the triangle across edge e
// of t, the edge from tris_[t][e] to tris_[t][e + 1], or -1 on the polygon's boundary. Edges
// without a neighbour are exactly the constrained ones (the polygon's sides and their pieces),
// so no other edge is ever kept from flipping. Every operation is O(1) but the point location
// walk, which starts where the previous insertion ended.
class Mesh {
 public:
  explicit Mesh(std::span<const Vec2> p) : p_(p), vertex_tri_(p.size(), -1) {}

  // Adds a triangle without neighbours (ear clipping); connect() links them afterwards.
  void add(uint32_t a, uint32_t b, uint32_t c) {
    tris_.push_back({a, b, c});
    nbr_.push_back({-1, -1, -1});
    touch(uint32_t(tris_.size() - 1));
  }
  // Links every pair of triangles sharing an edge (after ear clipping; O(t log t)).
  void connect() {
    std::map<std::pair<uint32_t, uint32_t>, std::pair<uint32_t, int>> edge;
    for (uint32_t t = 0; t < tris_.size(); ++t)
      for (int e = 0; e < 3; ++e) edge[{tris_[t][e], tris_[t][(e + 1) % 3]}] = {t, e};
    for (uint32_t t = 0; t < tris_.size(); ++t)
      for (int e = 0; e < 3; ++e) {
        const auto it = edge.find({tris_[t][(e + 1) % 3], tris_[t][e]});
        nbr_[t][e] = it == edge.end() ? -1 : int32_t(it->second.first);
      }
  }

  // Lawson flips from edge e of triangle t, whose third vertex is the point p just added: an
  // edge whose neighbour's far vertex lies inside the circumcircle is flipped, and the two
  // edges the flip exposes to p are checked in turn.
  void legalize(uint32_t t0, int e0) {
    stack_.assign(1, {t0, e0});
    while (!stack_.empty()) {
      const auto [t, e] = stack_.back();
      stack_.pop_back();
      const int32_t u = nbr_[t][e];
      if (u < 0) continue;  // a side of the polygon
      const uint32_t x = tris_[t][e], y = tris_[t][(e + 1) % 3], p = tris_[t][(e + 2) % 3];
      const int f = edge_index(uint32_t(u), y, x);
      const uint32_t q = tris_[u][(f + 2) % 3];
      if (!(incircle(p_[x], p_[y], p_[p], p_[q]) > 0)) continue;
      // The flip must keep both triangles positive (a convex quadrilateral).
      if (!(orient(p_[x], p_[q], p_[p]) > 0 && orient(p_[q], p_[y], p_[p]) > 0)) continue;
      const int32_t A = nbr_[t][(e + 1) % 3], B = nbr_[t][(e + 2) % 3];  // across y-p, p-x
      const int32_t C = nbr_[u][(f + 1) % 3], D = nbr_[u][(f + 2) % 3];  // across x-q, q-y
      tris_[t] = {x, q, p};
      nbr_[t] = {C, int32_t(u), B};
      tris_[u] = {q, y, p};
      nbr_[u] = {D, A, int32_t(t)};
      relink(A, t, uint32_t(u));
      relink(C, uint32_t(u), t);
      touch(t);
      touch(uint32_t(u));
      stack_.push_back({t, 0});
      stack_.push_back({uint32_t(u), 0});
    }
  }

  // Splits the triangle on the boundary edge a->b at p (which lies on that edge).
  void split_edge(uint32_t a, uint32_t b, uint32_t p) {
    const long t = find(a, b);
    if (t < 0) throw std::invalid_argument("polygon triangulation lost a boundary edge");
    const int e = edge_index(uint32_t(t), a, b);
    const uint32_t c = tris_[t][(e + 2) % 3];
    const int32_t N1 = nbr_[t][(e + 1) % 3], N2 = nbr_[t][(e + 2) % 3];  // across b-c, c-a
    const uint32_t t1 = uint32_t(tris_.size());
    tris_[t] = {a, p, c};
    nbr_[t] = {-1, int32_t(t1), N2};
    tris_.push_back({p, b, c});
    nbr_.push_back({-1, N1, int32_t(t)});
    relink(N1, uint32_t(t), t1);
    touch(uint32_t(t));
    touch(t1);
    legalize(t1, 1);           // b-c, against p
    legalize(uint32_t(t), 2);  // c-a, against p
  }

  // Inserts an interior point; returns false if it coincides with a vertex, lies on the polygon's
  // boundary or outside every triangle. A point exactly on an inner edge splits it.
  bool insert(uint32_t p) {
    const long found = locate(p);
    if (found < 0) return false;
    const uint32_t t = uint32_t(found);
    const auto [a, b, c] = tris_[t];
    const double o[3] = {orient(p_[a], p_[b], p_[p]), orient(p_[b], p_[c], p_[p]),
                         orient(p_[c], p_[a], p_[p])};
    const int zeros = (o[0] == 0) + (o[1] == 0) + (o[2] == 0);
    if (zeros > 1) return false;  // p is a vertex already
    hint_ = t;
    // On an edge: grid points are often collinear with an edge between two earlier points of
    // their row (any insertion order but raster order makes such edges); split it.
    for (int e = 0; e < 3; ++e)
      if (o[e] == 0) return insert_on_edge(t, e, p);
    const int32_t N1 = nbr_[t][1], N2 = nbr_[t][2];
    const uint32_t t1 = uint32_t(tris_.size()), t2 = t1 + 1;
    tris_[t] = {a, b, p};
    nbr_[t] = {nbr_[t][0], int32_t(t1), int32_t(t2)};
    tris_.push_back({b, c, p});
    nbr_.push_back({N1, int32_t(t2), int32_t(t)});
    tris_.push_back({c, a, p});
    nbr_.push_back({N2, int32_t(t), int32_t(t1)});
    relink(N1, t, t1);
    relink(N2, t, t2);
    touch(t);
    touch(t1);
    touch(t2);
    legalize(t, 0);
    legalize(t1, 0);
    legalize(t2, 0);
    return true;
  }

  const std::vector<std::array<uint32_t, 3>>& triangles() const { return tris_; }

 private:
  // p lies on edge e of triangle t, inside the segment: both triangles on the edge are split in
  // two. False on a boundary edge (p is not an interior point).
  bool insert_on_edge(uint32_t t, int e, uint32_t p) {
    const int32_t u = nbr_[t][e];
    if (u < 0) return false;
    const uint32_t x = tris_[t][e], y = tris_[t][(e + 1) % 3], c = tris_[t][(e + 2) % 3];
    const int f = edge_index(uint32_t(u), y, x);
    const uint32_t d = tris_[u][(f + 2) % 3];
    const int32_t A = nbr_[t][(e + 1) % 3], B = nbr_[t][(e + 2) % 3];  // across y-c, c-x
    const int32_t C = nbr_[u][(f + 1) % 3], D = nbr_[u][(f + 2) % 3];  // across x-d, d-y
    const uint32_t t1 = uint32_t(tris_.size()), u1 = t1 + 1;
    tris_[t] = {x, p, c};
    nbr_[t] = {int32_t(u1), int32_t(t1), B};
    tris_.push_back({p, y, c});
    nbr_.push_back({u, A, int32_t(t)});
    tris_[u] = {y, p, d};
    nbr_[u] = {int32_t(t1), int32_t(u1), D};
    tris_.push_back({p, x, d});
    nbr_.push_back({int32_t(t), C, u});
    relink(A, t, t1);
    relink(C, uint32_t(u), u1);
    for (uint32_t k : {t, t1, uint32_t(u), u1}) touch(k);
    legalize(t1, 1);           // y-c, against p
    legalize(t, 2);            // c-x
    legalize(u1, 1);           // x-d
    legalize(uint32_t(u), 2);  // d-y
    return true;
  }

  int edge_index(uint32_t t, uint32_t a, uint32_t b) const {
    for (int e = 0; e < 3; ++e)
      if (tris_[t][e] == a && tris_[t][(e + 1) % 3] == b) return e;
    throw std::logic_error("polygon triangulation: edge not in its triangle");
  }
  // The neighbour n (if any) pointed to `from`; it now points to `to`.
  void relink(int32_t n, uint32_t from, uint32_t to) {
    if (n < 0) return;
    for (int32_t& m : nbr_[n])
      if (m == int32_t(from)) m = int32_t(to);
  }
  void touch(uint32_t t) {
    for (uint32_t v : tris_[t]) vertex_tri_[v] = int32_t(t);
  }
  // The triangle holding the directed edge a->b, or -1: a turn around a from any triangle at a.
  long find(uint32_t a, uint32_t b) const {
    const int32_t start = vertex_tri_[a];
    for (int dir = 0; dir < 2 && start >= 0; ++dir) {
      int32_t t = start;
      for (std::size_t guard = 0; t >= 0 && guard <= tris_.size(); ++guard) {
        int i = 0;
        while (tris_[t][i] != a) ++i;
        if (tris_[t][(i + 1) % 3] == b) return t;
        // Outgoing edge a->v[i+1] (index i) or incoming edge v[i+2]->a (index i+2).
        t = nbr_[t][dir == 0 ? i : (i + 2) % 3];
        if (t == start) break;
      }
    }
    return -1;
  }
  // The triangle holding p (inside or on its boundary), or -1. Walks from the triangle of the
  // previous insertion towards p, crossing an edge that p lies beyond (points are inserted in
  // grid order, so the walk is short: O(1) per point instead of a scan of every triangle). A
  // walk that meets the polygon's boundary or runs long (a concave polygon can hide p behind
  // its boundary) falls back to the scan.
  long locate(uint32_t p) const {
    if (tris_.empty()) return -1;
    uint32_t t = hint_ < tris_.size() ? hint_ : 0;
    const std::size_t budget = 64 + 4 * static_cast<std::size_t>(std::sqrt(double(tris_.size())));
    for (std::size_t step = 0; step < budget; ++step) {
      const auto& v = tris_[t];
      int beyond = -1;  // the edge p lies farthest beyond
      double lowest = 0;
      for (int e = 0; e < 3; ++e) {
        const double o = orient(p_[v[e]], p_[v[(e + 1) % 3]], p_[p]);
        if (o < lowest) lowest = o, beyond = e;
      }
      if (beyond < 0) return long(t);
      if (nbr_[t][beyond] < 0) break;
      t = uint32_t(nbr_[t][beyond]);
    }
    for (uint32_t u = 0; u < tris_.size(); ++u) {
      const auto [a, b, c] = tris_[u];
      if (orient(p_[a], p_[b], p_[p]) >= 0 && orient(p_[b], p_[c], p_[p]) >= 0 &&
          orient(p_[c], p_[a], p_[p]) >= 0)
        return long(u);
    }
    return -1;
  }

  std::span<const Vec2> p_;
  std::vector<std::array<uint32_t, 3>> tris_;
  std::vector<std::array<int32_t, 3>> nbr_;
  std::vector<int32_t> vertex_tri_;              // a triangle at each vertex (-1 before it is used)
  std::vector<std::pair<uint32_t, int>> stack_;  // legalize's work list, kept to reuse its memory
  uint32_t hint_ = 0;  // the triangle of the last insertion: where the next walk starts
};

// Ear clipping of the polygon's corners (the points whose turn is not straight).
void clip_ears(std::span<const Vec2> p, std::vector<uint32_t> poly, Mesh& mesh) {
  while (poly.size() > 3) {
    const std::size_t n = poly.size();
    bool clipped = false;
    for (std::size_t i = 0; i < n && !clipped; ++i) {
      const uint32_t a = poly[(i + n - 1) % n], b = poly[i], c = poly[(i + 1) % n];
      if (!(orient(p[a], p[b], p[c]) > 0)) continue;
      bool blocked = false;
      for (uint32_t q : poly) {
        if (q == a || q == b || q == c) continue;
        if (orient(p[a], p[b], p[q]) >= 0 && orient(p[b], p[c], p[q]) >= 0 &&
            orient(p[c], p[a], p[q]) >= 0) {
          blocked = true;
          break;
        }
      }
      if (blocked) continue;
      mesh.add(a, b, c);
      poly.erase(poly.begin() + static_cast<long>(i));
      clipped = true;
    }
    if (!clipped) throw std::invalid_argument("polygon has no ear: it is not simple");
  }
  if (!(orient(p[poly[0]], p[poly[1]], p[poly[2]]) > 0))
    throw std::invalid_argument("polygon has no ear: it is not simple");
  mesh.add(poly[0], poly[1], poly[2]);
}

// Interior points in a biased randomised order (rounds of doubling size, each along a Morton
// curve): every round refines the last evenly, so an insertion flips few edges and the walk from
// the previous point is short. In raster order each row was inserted into the long triangles
// left by the boundary and flipped O(N) edges per point (density 512 took 12 s). The Delaunay
// triangulation does not depend on the order (points in general position).
std::vector<uint32_t> insertion_order(std::span<const Vec2> points, std::size_t first) {
  std::vector<uint32_t> order;
  for (std::size_t q = first; q < points.size(); ++q) order.push_back(static_cast<uint32_t>(q));
  if (order.size() < 64) return order;
  uint64_t state = 0x9e3779b97f4a7c15ull;  // fixed seed: the same tessellation every run
  for (std::size_t i = order.size() - 1; i > 0; --i) {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    std::swap(order[i], order[(state >> 33) % (i + 1)]);
  }
  Vec2 lo = points[order[0]], hi = lo;
  for (uint32_t q : order) lo = glm::min(lo, points[q]), hi = glm::max(hi, points[q]);
  const Vec2 extent = glm::max(hi - lo, Vec2(1e-300));
  const auto morton = [&](uint32_t q) {
    const Vec2 t = (points[q] - lo) / extent;
    const auto x = static_cast<uint32_t>(std::clamp(t.x, 0.0, 1.0) * 65535);
    const auto y = static_cast<uint32_t>(std::clamp(t.y, 0.0, 1.0) * 65535);
    uint64_t key = 0;
    for (int b = 0; b < 16; ++b)
      key |= uint64_t((x >> b) & 1) << (2 * b) | uint64_t((y >> b) & 1) << (2 * b + 1);
    return key;
  };
  // Rounds [0, 32), [32, 64), [64, 128), ... of the shuffled points, each sorted by its key.
  for (std::size_t b = 0, e = 32; b < order.size(); b = e, e = std::min(order.size(), 2 * e))
    std::sort(order.begin() + long(b), order.begin() + long(e),
              [&](uint32_t u, uint32_t v) { return morton(u) < morton(v); });
  return order;
}

}  // namespace

std::vector<std::array<uint32_t, 3>> triangulate_polygon(std::span<const Vec2> points,
                                                         std::size_t boundary_count,
                                                         const std::vector<uint32_t>& corners,
                                                         std::vector<bool>* used) {
  const std::size_t m = boundary_count;
  if (m < 3 || corners.size() < 3) throw std::invalid_argument("a polygon needs 3 corners");
  // Corners first (ear clipping + Delaunay flips), then interior points, then the
  // straight-angle boundary points split their boundary edges: each step keeps the
  // triangulation constrained-Delaunay.
  Mesh mesh(points);
  clip_ears(points, corners, mesh);
  mesh.connect();
  const std::size_t nc = corners.size();
  // Flip the ear-clipping diagonals to Delaunay: re-legalising each triangle's edges against
  // its third vertex until nothing changes.
  // Bounded: with cocircular corners rounding could otherwise flip one diagonal back and forth.
  for (int pass = 0, changed = 1; changed && pass < 64; ++pass) {
    const auto before = mesh.triangles();
    for (std::size_t t = 0; t < before.size(); ++t) mesh.legalize(uint32_t(t), 0);
    changed = before != mesh.triangles();
  }
  std::vector<bool> in(points.size(), false);
  for (uint32_t c : corners) in[c] = true;
  // Interior points before the boundary points: a point on a side of the corner polygon lies
  // inside the circumcircle of every triangle spanning the polygon, so inserted first it would
  // flip edges all across it (quadratic in the number of sides); after the interior points the
  // triangles next to a side are small and its points flip only their neighbours.
  for (const uint32_t q : insertion_order(points, m)) in[q] = mesh.insert(q);
  for (std::size_t c = 0; c < nc; ++c) {
    const uint32_t a = corners[c], b = corners[(c + 1) % nc];
    uint32_t prev = a;
    for (uint32_t q = (a + 1) % m; q != b; q = (q + 1) % m) {
      mesh.split_edge(prev, b, q);
      in[q] = true;
      prev = q;
    }
  }
  if (used) *used = in;
  return mesh.triangles();
}

}  // namespace pl
