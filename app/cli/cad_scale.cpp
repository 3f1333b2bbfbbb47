#include "app/cli/cad_scale.hpp"

#include <limits>

#include "core/base/data_error.hpp"
#include "core/io/json_node.hpp"
#include "core/patch/control_net_topology.hpp"

namespace pl {

double scene_point_size(const Scene& scene) {
  Vec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  bool any = false;
  auto add = [&](const Vec3& p) { lo = glm::min(lo, p), hi = glm::max(hi, p), any = true; };
  if (scene.network) {
    for (const Vec3& v : scene.network->vertices) add(v);
    for (const NetworkEdge& e : scene.network->edges) add(e.handles[0]), add(e.handles[1]);
  }
  for (const ScenePatch& sp : scene.patches) {
    const ControlNetTopology t = control_net_topology(*sp.patch);
    for (std::size_t k = 0; k < sp.patch->size(); ++k)
      if (!t.is_vector[k]) add(sp.patch->control_point(k));
  }
  for (const SceneCurve& c : scene.curves)
    for (const Vec3& p : c.points) add(p);
  return any ? glm::length(hi - lo) : 0.0;
}

void check_cad_scale(const Scene& scene, const std::string& source) {
  const double size = scene_point_size(scene);
  if (size == 0 || (size >= kMinCadSize && size <= kMaxCadSize)) return;
  throw DataError(source, "",
                  "STEP and IGES export scenes whose size is from " + short_number(kMinCadSize) +
                      " to " + short_number(kMaxCadSize) + " units; this one's is " +
                      short_number(size) + " (scale it into that range first)");
}

}  // namespace pl
