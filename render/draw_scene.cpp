#include "render/draw_scene.hpp"

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
