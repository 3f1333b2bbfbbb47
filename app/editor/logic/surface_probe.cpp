#include "app/editor/logic/surface_probe.hpp"

#include <cmath>
#include <limits>

namespace pl {

std::optional<ProbeHit> probe_surfaces(std::span<const SurfaceMesh> meshes, const Ray& ray) {
  std::optional<ProbeHit> best;
  double best_t = std::numeric_limits<double>::infinity();
  for (std::size_t m = 0; m < meshes.size(); ++m) {
    const SurfaceMesh& mesh = meshes[m];
    for (const auto& tri : mesh.triangles) {
      const Vec3 &a = mesh.positions[tri[0]], &b = mesh.positions[tri[1]],
                 &c = mesh.positions[tri[2]];
      const Vec3 e1 = b - a, e2 = c - a;
      const Vec3 p = glm::cross(ray.direction, e2);
      const double det = glm::dot(e1, p);
      // Relative to the triangle's size: a ray grazing the triangle's plane misses it.
      if (std::abs(det) <= 1e-14 * glm::dot(e1, e1)) continue;
      const double inv = 1 / det;
      const Vec3 s = ray.origin - a;
      const double u = glm::dot(s, p) * inv;
      if (u < 0 || u > 1) continue;
      const Vec3 q = glm::cross(s, e1);
      const double v = glm::dot(ray.direction, q) * inv;
      if (v < 0 || u + v > 1) continue;
      const double t = glm::dot(e2, q) * inv;
      if (t <= 0 || t >= best_t) continue;
      best_t = t;
      const double w = 1 - u - v;
      auto mix = [&](const std::vector<double>& f) {
        return w * f[tri[0]] + u * f[tri[1]] + v * f[tri[2]];
      };
      ProbeHit h;
      h.surface = static_cast<int>(m);
      h.distance = t;
      h.position = ray.origin + t * ray.direction;
      const Vec3 n = w * mesh.normals[tri[0]] + u * mesh.normals[tri[1]] + v * mesh.normals[tri[2]];
      h.normal = glm::length(n) > 0 ? glm::normalize(n) : n;
      h.k1 = mix(mesh.kmax);
      h.k2 = mix(mesh.kmin);
      h.gaussian = mix(mesh.gaussian);
      h.mean = mix(mesh.mean);
      best = h;
    }
  }
  return best;
}

}  // namespace pl
