#include "core/domain/polygon_triangulation.hpp"

#include <algorithm>
#include <stdexcept>
#include <unordered_map>
#include <unordered_set>

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

uint64_t key(uint32_t a, uint32_t b) {
  return (uint64_t(a) << 32) | b;
}

// Triangles with a directed-edge index, so the neighbour across an edge is one lookup.
class Mesh {
 public:
  explicit Mesh(std::span<const Vec2> p) : p_(p) {}

  void add(uint32_t a, uint32_t b, uint32_t c) {
    tris_.push_back({a, b, c});
    link(static_cast<uint32_t>(tris_.size() - 1));
  }
  void replace(uint32_t t, uint32_t a, uint32_t b, uint32_t c) {
    unlink(t);
    tris_[t] = {a, b, c};
    link(t);
  }
  // The triangle holding the directed edge a->b, or -1.
  long find(uint32_t a, uint32_t b) const {
    const auto it = edges_.find(key(a, b));
    return it == edges_.end() ? -1 : long(it->second);
  }
  uint32_t third(uint32_t t, uint32_t a, uint32_t b) const {
    for (uint32_t v : tris_[t])
      if (v != a && v != b) return v;
    return a;
  }
  void constrain(uint32_t a, uint32_t b) { fixed_.insert(key(std::min(a, b), std::max(a, b))); }
  void release(uint32_t a, uint32_t b) { fixed_.erase(key(std::min(a, b), std::max(a, b))); }
  bool is_fixed(uint32_t a, uint32_t b) const {
    return fixed_.count(key(std::min(a, b), std::max(a, b))) != 0;
  }

  // Lawson flips around the new point p: (a, b) is an edge of the triangle (a, b, p).
  void legalize(uint32_t a, uint32_t b, uint32_t p) {
    std::vector<std::array<uint32_t, 2>> stack{{a, b}};
    while (!stack.empty()) {
      const auto [x, y] = stack.back();
      stack.pop_back();
      if (is_fixed(x, y)) continue;
      const long u = find(y, x), t = find(x, y);
      if (u < 0 || t < 0) continue;
      const uint32_t q = third(uint32_t(u), y, x);
      if (!(incircle(p_[x], p_[y], p_[p], p_[q]) > 0)) continue;
      // The flip must keep both triangles positive (a convex quadrilateral).
      if (!(orient(p_[x], p_[q], p_[p]) > 0 && orient(p_[q], p_[y], p_[p]) > 0)) continue;
      // Both triangles leave the edge index before either returns: the new (x, q, p) reuses
      // the directed edge x->q of the old (y, x, q).
      unlink(uint32_t(t));
      unlink(uint32_t(u));
      tris_[t] = {x, q, p};
      tris_[u] = {q, y, p};
      link(uint32_t(t));
      link(uint32_t(u));
      stack.push_back({x, q});
      stack.push_back({q, y});
    }
  }

  // Splits the triangle on the directed edge a->b at p (which lies on that edge).
  void split_edge(uint32_t a, uint32_t b, uint32_t p) {
    const long t = find(a, b);
    if (t < 0) throw std::invalid_argument("polygon triangulation lost a boundary edge");
    const uint32_t c = third(uint32_t(t), a, b);
    replace(uint32_t(t), a, p, c);
    add(p, b, c);
    release(a, b);
    constrain(a, p);
    constrain(p, b);
    legalize(b, c, p);
    legalize(c, a, p);
  }

  // Inserts an interior point; returns false if it lies on an edge or outside every triangle.
  bool insert(uint32_t p) {
    const long found = locate(p);
    for (uint32_t t = found < 0 ? 0 : uint32_t(found); t < tris_.size(); ++t) {
      const auto [a, b, c] = tris_[t];
      const double o1 = orient(p_[a], p_[b], p_[p]), o2 = orient(p_[b], p_[c], p_[p]);
      const double o3 = orient(p_[c], p_[a], p_[p]);
      if (o1 < 0 || o2 < 0 || o3 < 0) continue;
      const int zeros = (o1 == 0) + (o2 == 0) + (o3 == 0);
      if (zeros > 1) return false;  // p is a vertex already
      last_ = t;
      // On an edge: grid points are often collinear with an edge between two earlier points of
      // their row (any insertion order but raster order makes such edges); split it.
      if (o1 == 0) return insert_on_edge(t, a, b, p);
      if (o2 == 0) return insert_on_edge(t, b, c, p);
      if (o3 == 0) return insert_on_edge(t, c, a, p);
      replace(t, a, b, p);
      add(b, c, p);
      add(c, a, p);
      legalize(a, b, p);
      legalize(b, c, p);
      legalize(c, a, p);
      return true;
    }
    return false;
  }

  const std::vector<std::array<uint32_t, 3>>& triangles() const { return tris_; }

 private:
  // p lies on the edge x->y of triangle t (inside the segment): both triangles on the edge are
  // split in two. False on a boundary edge (p is not an interior point).
  bool insert_on_edge(uint32_t t, uint32_t x, uint32_t y, uint32_t p) {
    const long u = find(y, x);
    if (u < 0 || is_fixed(x, y)) return false;
    const uint32_t c = third(t, x, y), d = third(uint32_t(u), y, x);
    replace(t, x, p, c);
    add(p, y, c);
    replace(uint32_t(u), y, p, d);
    add(p, x, d);
    legalize(y, c, p);
    legalize(c, x, p);
    legalize(x, d, p);
    legalize(d, y, p);
    return true;
  }

  // The triangle holding p, found by walking from the last insertion towards p (interior points
  // come in tessellation order, so the walk is short): O(1) per point where scanning every
  // triangle made the whole tessellation O(N^2) (density 128 took seconds, 1000 hours). Where the
  // walk leaves the polygon or does not settle, -1: the caller scans from the first triangle.
  long locate(uint32_t p) const {
    uint32_t t = last_ < tris_.size() ? last_ : 0;
    for (std::size_t step = 0; step < tris_.size(); ++step) {
      const auto& v = tris_[t];
      int worst = -1;
      double lowest = 0;
      for (int i = 0; i < 3; ++i) {
        const double o = orient(p_[v[i]], p_[v[(i + 1) % 3]], p_[p]);
        if (o < lowest) lowest = o, worst = i;
      }
      if (worst < 0) return long(t);
      const long next = find(v[(worst + 1) % 3], v[worst]);
      if (next < 0) return -1;
      t = uint32_t(next);
    }
    return -1;
  }

  uint32_t last_ = 0;
  void link(uint32_t t) {
    const auto& v = tris_[t];
    for (int i = 0; i < 3; ++i) edges_[key(v[i], v[(i + 1) % 3])] = t;
  }
  void unlink(uint32_t t) {
    const auto& v = tris_[t];
    for (int i = 0; i < 3; ++i) edges_.erase(key(v[i], v[(i + 1) % 3]));
  }

  std::span<const Vec2> p_;
  std::vector<std::array<uint32_t, 3>> tris_;
  std::unordered_map<uint64_t, uint32_t> edges_;
  std::unordered_set<uint64_t> fixed_;
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
  // Corners first (ear clipping + Delaunay flips), then the straight-angle boundary points
  // split their boundary edges, then interior points: each step keeps the triangulation
  // constrained-Delaunay.
  Mesh mesh(points);
  clip_ears(points, corners, mesh);
  const std::size_t nc = corners.size();
  for (std::size_t c = 0; c < nc; ++c) mesh.constrain(corners[c], corners[(c + 1) % nc]);
  // Flip the ear-clipping diagonals to Delaunay: re-legalising each triangle's edges against
  // its third vertex until nothing changes.
  // Bounded: with cocircular corners rounding could otherwise flip one diagonal back and forth.
  for (int pass = 0, changed = 1; changed && pass < 64; ++pass) {
    const auto before = mesh.triangles();
    for (std::size_t t = 0; t < before.size(); ++t) {
      const auto [a, b, c] = mesh.triangles()[t];
      mesh.legalize(a, b, c);
    }
    changed = before != mesh.triangles();
  }
  std::vector<bool> in(points.size(), false);
  for (uint32_t c : corners) in[c] = true;
  for (std::size_t c = 0; c < nc; ++c) {
    const uint32_t a = corners[c], b = corners[(c + 1) % nc];
    uint32_t prev = a;
    for (uint32_t q = (a + 1) % m; q != b; q = (q + 1) % m) {
      mesh.split_edge(prev, b, q);
      in[q] = true;
      prev = q;
    }
  }
  for (const uint32_t q : insertion_order(points, m)) in[q] = mesh.insert(q);
  if (used) *used = in;
  return mesh.triangles();
}

}  // namespace pl
