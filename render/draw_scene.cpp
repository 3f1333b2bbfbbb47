#include "render/draw_scene.hpp"

#include <cmath>

namespace pl {

uint32_t point_style_bits(const ControlNet& net) {
  uint32_t bits = 0;
  for (std::size_t i = 0; i < net.points.size(); ++i)
    bits |= 1u << point_style_tag(i < net.kinds.size() ? net.kinds[i] : ControlPointKind::Boundary,
                                  net.role(i));
  return bits;
}

uint32_t arrow_kind_bits(const std::vector<Arrow>& arrows) {
  uint32_t bits = 0;
  for (const Arrow& a : arrows) bits |= 1u << static_cast<int>(a.kind);
  return bits;
}

int enclosed_volume_sign(const std::vector<SurfaceMesh>& meshes) {
  // About the meshes' own centre, so that a solid far from the origin loses nothing to
  // cancellation, compared with the volume of their box.
  Box box;
  for (const SurfaceMesh& m : meshes)
    for (const Vec3& p : m.positions) box.add(p);
  if (box.empty()) return 0;
  const Vec3 c = 0.5 * (box.lo + box.hi);
  double volume = 0;
  for (const SurfaceMesh& m : meshes)
    for (const auto& t : m.triangles) {
      const Vec3 a = m.positions[t[0]] - c, b = m.positions[t[1]] - c, d = m.positions[t[2]] - c;
      volume += glm::dot(a, glm::cross(b, d));  // six times the signed tetrahedron volume
    }
  const Vec3 size = box.hi - box.lo;
  const double diagonal = glm::length(size);
  if (!(std::abs(volume) > 1e-9 * diagonal * diagonal * diagonal)) return 0;
  return volume > 0 ? 1 : -1;
}

Box DrawScene::bounds() const {
  Box b;
  for (const SurfaceMesh& m : surfaces)
    for (const Vec3& p : m.positions) b.add(p);
  for (const Vec3& p : net.points) b.add(p);
  for (const Arrow& a : arrows) {
    b.add(a.base);
    b.add(a.tip);
  }
  for (const Polyline& l : network_curves)
    for (const Vec3& p : l) b.add(p);
  for (const Polyline& l : free_curves)
    for (const Vec3& p : l) b.add(p);
  return b;
}

}  // namespace pl
