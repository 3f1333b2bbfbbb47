// Every control point the editor shows, with the PointRef of those a user may move (network
// vertices, edge handles, explicit patch points) and none for derived points (Gregory twins, GB
// ribbon and central points of network faces), plus the control-net segments and curves drawn
// over the surfaces. GUI-free: picking and drawing both read this one list.
#pragma once

#include <optional>
#include <vector>

#include "app/document/point_ref.hpp"
#include "core/eval/scene_surfaces.hpp"
#include "render/draw_scene.hpp"

namespace pl {

struct ScenePoints {
  std::vector<Vec3> positions;
  std::vector<ControlPointKind> kinds;
  std::vector<std::optional<PointRef>> refs;  // nullopt: derived, shown but not editable
  std::vector<std::array<uint32_t, 2>> segments;

  std::vector<bool> editable() const;
  int find(const PointRef& ref) const;  // index of ref, or -1
};

ScenePoints collect_scene_points(const Scene& scene, const SceneSurfaces& surfaces);

// The overlays of a DrawScene from the points: the net and the network curves. Borders and
// curvature combs are LiveCurves'.
void fill_overlays(const Scene& scene, const ScenePoints& points, DrawScene& draw);

}  // namespace pl
