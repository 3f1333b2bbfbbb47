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
  h.triangle = static_cast<int>(hit.triangle);
  h.b1 = u;
  h.b2 = v;
  h.position = ray.origin + hit.t * ray.direction;
  const Vec3 n = w * mesh.normals[tri[0]] + u * mesh.normals[tri[1]] + v * mesh.normals[tri[2]];
  h.normal = glm::length(n) > 0 ? glm::normalize(n) : n;
  h.k1 = mix(mesh.kmax);
  h.k2 = mix(mesh.kmin);
  h.gaussian = mix(mesh.gaussian);
  h.mean = mix(mesh.mean);
  return h;
}

std::optional<double> probe_field(const SurfaceMesh& mesh, const std::vector<double>& field,
                                  const ProbeHit& probe) {
  if (probe.triangle < 0 || std::size_t(probe.triangle) >= mesh.triangles.size()) return {};
  const auto& tri = mesh.triangles[probe.triangle];
  for (auto i : tri)
    if (std::size_t(i) >= field.size()) return {};
  return (1 - probe.b1 - probe.b2) * field[tri[0]] + probe.b1 * field[tri[1]] +
         probe.b2 * field[tri[2]];
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
