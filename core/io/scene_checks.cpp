#include "core/io/scene_checks.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/base/data_error.hpp"
#include "core/io/input_limits.hpp"
#include "core/io/json_node.hpp"

namespace pl {

namespace {

// The boundary of a face sampled along its sides, side i from loop[i] to loop[i+1].
constexpr int kSamplesPerSide = 16;
std::vector<Vec3> sampled_boundary(const Network& net, const std::vector<FaceSide>& sides) {
  std::vector<Vec3> pts;
  for (const FaceSide& s : sides) {
    const BezierCurve c = net.edge_curve(s.edge);
    for (int k = 0; k < kSamplesPerSide; ++k) {
      const double t = double(k) / kSamplesPerSide;
      pts.push_back(c.point(s.reversed ? 1 - t : t));
    }
  }
  return pts;
}

// The direction the face is seen from: Newell's normal of the loop, or where that vanishes
// (a planar figure eight), the normal of the plane fitted to the points.
Vec3 viewing_normal(const std::vector<Vec3>& p) {
  Vec3 n(0);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec3& a = p[i];
    const Vec3& b = p[(i + 1) % p.size()];
    n += Vec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
  }
  const double s = span_of(p);
  if (glm::length(n) > 1e-9 * s * s) return glm::normalize(n);
  Vec3 c(0);
  for (const Vec3& q : p) c += q;
  c /= double(p.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const Vec3& q : p) {
    const Eigen::Vector3d d((q.x - c.x) / s, (q.y - c.y) / s, (q.z - c.z) / s);
    cov += d * d.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
  const Eigen::Vector3d v = eig.eigenvectors().col(0);  // smallest eigenvalue first
  return {v.x(), v.y(), v.z()};
}

double orient(const Vec2& a, const Vec2& b, const Vec2& c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

bool on_segment(const Vec2& a, const Vec2& b, const Vec2& p) {
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
         p.y <= std::max(a.y, b.y);
}

bool segments_meet(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  const double o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a),
               o4 = orient(c, d, b);
  if (((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0)))
    return true;
  return (o1 == 0 && on_segment(a, b, c)) || (o2 == 0 && on_segment(a, b, d)) ||
         (o3 == 0 && on_segment(c, d, a)) || (o4 == 0 && on_segment(c, d, b));
}

}  // namespace

void check_span(std::span<const Vec3> points, const std::string& source, const std::string& where) {
  if (points.size() < 2) return;
  const double s = span_of(points);
  if (!(s >= kMinSpan))
    throw DataError(source, where,
                    "the control points span only " + short_number(s) +
                        ": squared lengths underflow (the points must span at least " +
                        short_number(kMinSpan) + ")");
}

double span_of(std::span<const Vec3> points) {
  if (points.size() < 2) return 0;
  Vec3 lo = points[0], hi = points[0];
  for (const Vec3& p : points) lo = glm::min(lo, p), hi = glm::max(hi, p);
  const Vec3 e = hi - lo;
  // Scaled so that the length of an extent near the coordinate bound does not overflow.
  const double m = std::max({e.x, e.y, e.z});
  return m > 0 ? m * glm::length(e / m) : 0;
}

void check_spans(const Scene& scene, const std::string& source) {
  if (scene.network) {
    std::vector<Vec3> pts = scene.network->vertices;
    for (const NetworkEdge& e : scene.network->edges)
      pts.insert(pts.end(), e.handles.begin(), e.handles.end());
    check_span(pts, source, "network");
  }
  for (std::size_t i = 0; i < scene.patches.size(); ++i)
    check_span(scene.patches[i].patch->control_points(), source,
               "patches[" + std::to_string(i) + "]");
}

void check_face_loops(const Network& net, const NetworkTopology& topo, const std::string& source) {
  for (std::size_t f = 0; f < net.faces.size(); ++f) {
    const std::vector<Vec3> p = sampled_boundary(net, topo.face_sides[f]);
    const Vec3 n = viewing_normal(p);
    // A basis of the plane across n.
    const Vec3 a = std::fabs(n.x) < 0.6 ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
    const Vec3 u = glm::normalize(glm::cross(n, a)), v = glm::cross(n, u);
    std::vector<Vec2> q;
    q.reserve(p.size());
    for (const Vec3& x : p) q.emplace_back(glm::dot(x, u), glm::dot(x, v));
    const std::size_t m = q.size();
    std::vector<Vec2> lo(m), hi(m);
    for (std::size_t i = 0; i < m; ++i)
      lo[i] = glm::min(q[i], q[(i + 1) % m]), hi[i] = glm::max(q[i], q[(i + 1) % m]);
    for (std::size_t i = 0; i < m; ++i)
      for (std::size_t j = i + 2; j < m; ++j) {
        if (i == 0 && j == m - 1) continue;  // neighbours across the loop's start
        if (hi[i].x < lo[j].x || hi[j].x < lo[i].x || hi[i].y < lo[j].y || hi[j].y < lo[i].y)
          continue;
        if (!segments_meet(q[i], q[(i + 1) % m], q[j], q[(j + 1) % m])) continue;
        const std::size_t si = i / kSamplesPerSide, sj = j / kSamplesPerSide;
        throw DataError(source, "network.faces[" + std::to_string(f) + "].loop",
                        "the face's boundary crosses itself (side " + std::to_string(si) +
                            (si == sj ? " with itself" : " meets side " + std::to_string(sj)) +
                            ", seen along the face's normal): a face must be a simple loop");
      }
  }
}

void check_scene(const Scene& scene, const std::string& source) {
  check_spans(scene, source);
  if (scene.network)
    check_face_loops(*scene.network, validate_network(*scene.network, source), source);
}

}  // namespace pl
