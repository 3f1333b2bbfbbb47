#include "core/analysis/surface_energy.hpp"

#include <cmath>

namespace pl {

SurfaceIntegrals surface_integrals(const PatchEvaluator& ev) {
  SurfaceIntegrals r;
  const auto& geometry = ev.geometry();
  for (const auto& t : ev.tessellation().triangles) {
    const Vec3 a = ev.position(t[0]), b = ev.position(t[1]), c = ev.position(t[2]);
    const Vec3 twice = glm::cross(b - a, c - a);  // 2 A_T n_T
    const double twice_area = glm::length(twice);
    if (!(twice_area > 0)) continue;
    const double area = 0.5 * twice_area;
    const Vec3 n = twice / twice_area;
    const SurfaceGeometry &ga = geometry[t[0]], &gb = geometry[t[1]], &gc = geometry[t[2]];
    const auto bend = [](const SurfaceGeometry& g) { return g.kmin * g.kmin + g.kmax * g.kmax; };
    r.area += area;
    r.bending_energy += area * (bend(ga) + bend(gb) + bend(gc)) / 3.0;
    // The gradient of the linear interpolant: each vertex's hat function rises across the
    // opposite edge e_i, its gradient n × e_i / (2 A) (edges counter-clockwise about n).
    const Vec3 grad = (ga.mean * glm::cross(n, c - b) + gb.mean * glm::cross(n, a - c) +
                       gc.mean * glm::cross(n, b - a)) /
                      twice_area;
    r.mean_curvature_gradient_energy += area * glm::dot(grad, grad);
  }
  return r;
}

}  // namespace pl
