#include "render/draw_scene.hpp"

namespace pl {

Box DrawScene::bounds() const {
  Box b;
  for (const SurfaceMesh& m : surfaces)
    for (const Vec3& p : m.positions) b.add(p);
  for (const Vec3& p : net.points) b.add(p);
  for (const Polyline& l : network_curves)
    for (const Vec3& p : l) b.add(p);
  return b;
}

}  // namespace pl
