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

// The overlays of a DrawScene from the points: the net, and the network curves with their combs
// (comb_teeth tooth intervals per curve). Borders come from border_combs.
void fill_overlays(const Scene& scene, const ScenePoints& points, int comb_teeth, DrawScene& draw);

// The border combs of one surface, one per domain side; their points are the border polylines.
std::vector<CurvatureComb> border_combs(const SceneSurface& surface, int comb_teeth);

// Sets draw.borders, border_combs and border_on_network from per-surface border combs.
void fill_borders(const SceneSurfaces& surfaces,
                  const std::vector<std::vector<CurvatureComb>>& combs, DrawScene& draw);

}  // namespace pl
