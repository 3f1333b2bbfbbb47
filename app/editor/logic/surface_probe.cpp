#include "app/editor/logic/surface_probe.hpp"

#include <limits>

namespace pl {

ProbeHit probe_at(const SurfaceMesh& mesh, int surface, const TriangleHit& hit, const Ray& ray) {
  const auto& tri = mesh.triangles[hit.triangle];
  const double u = hit.b1, v = hit.b2, w = 1 - u - v;
  auto mix = [&](const std::vector<double>& f) {
    return w * f[tri[0]] + u * f[tri[1]] + v * f[tri[2]];
  };
  ProbeHit h;
  h.surface = surface;
  h.distance = hit.t;
  h.position = ray.origin + hit.t * ray.direction;
  const Vec3 n = w * mesh.normals[tri[0]] + u * mesh.normals[tri[1]] + v * mesh.normals[tri[2]];
  h.normal = glm::length(n) > 0 ? glm::normalize(n) : n;
  h.k1 = mix(mesh.kmax);
  h.k2 = mix(mesh.kmin);
  h.gaussian = mix(mesh.gaussian);
  h.mean = mix(mesh.mean);
  return h;
}

std::optional<ProbeHit> probe_surfaces(std::span<const SurfaceMesh> meshes, const Ray& ray) {
  std::optional<ProbeHit> best;
  double t_max = std::numeric_limits<double>::infinity();
  for (std::size_t m = 0; m < meshes.size(); ++m)
    if (const auto hit = intersect_all(ray, meshes[m].positions, meshes[m].triangles, t_max)) {
      t_max = hit->t;
      best = probe_at(meshes[m], static_cast<int>(m), *hit, ray);
    }
  return best;
}

}  // namespace pl
