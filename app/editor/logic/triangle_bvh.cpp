#include "app/editor/logic/triangle_bvh.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pl {

namespace {

// Triangles per leaf: fewer nodes (memory) against more exact tests per visited leaf.
constexpr uint32_t kLeafSize = 8;

float round_down(double v) {
  const float f = static_cast<float>(v);
  return double(f) <= v ? f : std::nextafter(f, -std::numeric_limits<float>::infinity());
}
float round_up(double v) {
  const float f = static_cast<float>(v);
  return double(f) >= v ? f : std::nextafter(f, std::numeric_limits<float>::infinity());
}

}  // namespace

std::optional<TriangleHit> intersect_triangle(const Ray& ray, const Vec3& a, const Vec3& b,
                                              const Vec3& c, double t_max) {
  const Vec3 e1 = b - a, e2 = c - a;
  const Vec3 p = glm::cross(ray.direction, e2);
  const double det = glm::dot(e1, p);
  if (std::abs(det) <= 1e-14 * glm::dot(e1, e1)) return std::nullopt;
  const double inv = 1 / det;
  const Vec3 s = ray.origin - a;
  const double u = glm::dot(s, p) * inv;
  if (u < 0 || u > 1) return std::nullopt;
  const Vec3 q = glm::cross(s, e1);
  const double v = glm::dot(ray.direction, q) * inv;
  if (v < 0 || u + v > 1) return std::nullopt;
  const double t = glm::dot(e2, q) * inv;
  if (!(t > 0 && t < t_max)) return std::nullopt;
  return TriangleHit{-1, t, u, v};
}

std::optional<TriangleHit> intersect_all(const Ray& ray, std::span<const Vec3> positions,
                                         Triangles triangles, double t_max) {
  std::optional<TriangleHit> best;
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    const auto& tri = triangles[i];
    if (auto h = intersect_triangle(ray, positions[tri[0]], positions[tri[1]], positions[tri[2]],
                                    t_max)) {
      h->triangle = static_cast<int>(i);
      t_max = h->t;
      best = h;
    }
  }
  return best;
}

std::optional<std::array<double, 2>> intersect_box(const Ray& ray, const Box& box, double t_max) {
  double t0 = 0, t1 = t_max;
  for (int k = 0; k < 3; ++k) {
    const double o = ray.origin[k], d = ray.direction[k];
    if (d == 0) {
      if (o < box.lo[k] || o > box.hi[k]) return std::nullopt;
      continue;
    }
    double a = (box.lo[k] - o) / d, b = (box.hi[k] - o) / d;
    if (a > b) std::swap(a, b);
    t0 = std::max(t0, a);
    t1 = std::min(t1, b);
    if (t0 > t1) return std::nullopt;
  }
  return std::array<double, 2>{t0, t1};
}

TriangleBvh::TriangleBvh(std::span<const Vec3> positions, Triangles triangles) {
  const auto n = static_cast<uint32_t>(triangles.size());
  order_.resize(n);
  std::vector<Vec3> centroids(n);
  for (uint32_t i = 0; i < n; ++i) {
    order_[i] = i;
    const auto& t = triangles[i];
    centroids[i] = (positions[t[0]] + positions[t[1]] + positions[t[2]]) / 3.0;
  }
  nodes_.reserve(n / kLeafSize * 2 + 1);
  if (n > 0) build(positions, triangles, centroids, 0, n);
}

uint32_t TriangleBvh::build(std::span<const Vec3> positions, Triangles triangles,
                            std::vector<Vec3>& centroids, uint32_t begin, uint32_t end) {
  const auto index = static_cast<uint32_t>(nodes_.size());
  nodes_.emplace_back();
  Box box, centres;
  for (uint32_t i = begin; i < end; ++i) {
    for (uint32_t v : triangles[order_[i]]) box.add(positions[v]);
    centres.add(centroids[order_[i]]);
  }
  for (int k = 0; k < 3; ++k) {
    nodes_[index].lo[k] = round_down(box.lo[k]);
    nodes_[index].hi[k] = round_up(box.hi[k]);
  }
  if (end - begin <= kLeafSize) {
    nodes_[index].first = begin;
    nodes_[index].count = end - begin;
    return index;
  }
  // Median split along the widest extent of the centroids.
  const Vec3 extent = centres.hi - centres.lo;
  const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
  const uint32_t mid = begin + (end - begin) / 2;
  std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
                   [&](uint32_t a, uint32_t b) { return centroids[a][axis] < centroids[b][axis]; });
  build(positions, triangles, centroids, begin, mid);
  const uint32_t right = build(positions, triangles, centroids, mid, end);
  nodes_[index].first = right;
  nodes_[index].count = 0;
  return index;
}

std::optional<TriangleHit> TriangleBvh::intersect(const Ray& ray, std::span<const Vec3> positions,
                                                  Triangles triangles, double t_max) const {
  std::optional<TriangleHit> best;
  if (nodes_.empty()) return best;
  uint32_t stack[64];
  int top = 0;
  stack[top++] = 0;
  auto box_of = [](const Node& n) {
    Box b;
    b.lo = Vec3(n.lo[0], n.lo[1], n.lo[2]);
    b.hi = Vec3(n.hi[0], n.hi[1], n.hi[2]);
    return b;
  };
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    if (!intersect_box(ray, box_of(node), t_max)) continue;
    if (node.count > 0) {
      for (uint32_t i = node.first; i < node.first + node.count; ++i) {
        const auto& tri = triangles[order_[i]];
        if (auto h = intersect_triangle(ray, positions[tri[0]], positions[tri[1]],
                                        positions[tri[2]], t_max)) {
          h->triangle = static_cast<int>(order_[i]);
          t_max = h->t;
          best = h;
        }
      }
      continue;
    }
    // Nearer child last, so it is visited first and shrinks t_max for the other one.
    const uint32_t left = static_cast<uint32_t>(&node - nodes_.data()) + 1, right = node.first;
    const auto tl = intersect_box(ray, box_of(nodes_[left]), t_max);
    const auto tr = intersect_box(ray, box_of(nodes_[right]), t_max);
    if (tl && tr) {
      const bool left_first = (*tl)[0] <= (*tr)[0];
      stack[top++] = left_first ? right : left;
      stack[top++] = left_first ? left : right;
    } else if (tl) {
      stack[top++] = left;
    } else if (tr) {
      stack[top++] = right;
    }
  }
  return best;
}

std::size_t TriangleBvh::memory_bytes() const {
  return nodes_.size() * sizeof(Node) + order_.size() * sizeof(uint32_t);
}

}  // namespace pl
