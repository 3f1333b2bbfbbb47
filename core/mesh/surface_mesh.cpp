#include "core/mesh/surface_mesh.hpp"

namespace pl {

SurfaceMesh make_surface_mesh(const PatchEvaluator& ev, std::string name) {
  SurfaceMesh m;
  m.name = std::move(name);
  const std::size_t n = ev.sample_count();
  m.positions.resize(n);
  m.normals.resize(n);
  m.gaussian.resize(n);
  m.mean.resize(n);
  m.kmin.resize(n);
  m.kmax.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const SurfaceGeometry& g = ev.geometry()[i];
    m.positions[i] = ev.position(i);
    m.normals[i] = g.normal;
    m.gaussian[i] = g.gaussian;
    m.mean[i] = g.mean;
    m.kmin[i] = g.kmin;
    m.kmax[i] = g.kmax;
  }
  // Domains are counter-clockwise and the normal is Su x Sv, so domain triangles are already
  // oriented towards the normal.
  m.triangles = ev.tessellation().triangles;
  m.params = ev.tessellation().points;
  m.revision = ev.revision();
  return m;
}

}  // namespace pl
