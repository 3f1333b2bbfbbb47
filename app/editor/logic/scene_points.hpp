// Every control point the editor shows, with the PointRef of those a user may move (network
// vertices, edge handles, explicit patch points, the free interior points of network GB faces)
// and none for derived points (Gregory twins, the G1 rows of GB faces), the control-net segments of
// every patch family (core/patch/control_net_topology.hpp: GB rows and spokes, Gregory twins,
// spline grids, the Catmull–Clark cage, ...) and the derivative data of explicit patches (Hermite
// tangents and twists, Coons network derivatives) as arrows, never as points. GUI-free: picking and
// drawing both read this one list.
//
// Layout: the network's vertices, then two handles per edge, then one group per explicit scene
// patch and one per network face (its free points, kind FreeInterior, then its derived points;
// its boundary points are the network's own and its free points' positions its free points',
// where they coincide exactly), then the free curves' points, curve after curve. Groups let
// an edit refresh the points of the surfaces it changed only (update_group).
#pragma once

#include <optional>
#include <vector>

#include "app/document/point_ref.hpp"
#include "core/eval/scene_surfaces.hpp"
#include "render/draw_scene.hpp"

namespace pl {

class IncrementalFilling;
struct EdgeCrossTangents;

// Whose a point is: a network vertex, an edge (its handles), an explicit scene patch, a
// network face (by surface index) or a free curve.
struct PointOwner {
  enum class Kind : uint8_t { Vertex, Edge, Patch, Face, Curve };
  Kind kind = Kind::Vertex;
  int index = -1;
  bool operator==(const PointOwner&) const = default;
};

struct ScenePoints {
  std::vector<Vec3> positions;
  std::vector<ControlPointKind> kinds;
  std::vector<std::optional<PointRef>> refs;  // nullopt: derived, shown but not editable
  std::vector<PointOwner> owners;
  std::vector<std::array<uint32_t, 2>> segments;  // each pair once
  std::vector<Arrow> arrows;                      // derivative vectors of explicit patches
  std::vector<uint32_t> arrow_base;               // per arrow: the point it starts at

  // The points of one explicit patch or network face: positions [first, first + ks.size()) are
  // its control points ks (vectors excluded), arrows [first_arrow, ...) its derivative arrows.
  struct Group {
    PointOwner owner;
    std::size_t first = 0;
    std::vector<uint32_t> ks;
    std::size_t first_arrow = 0;
    std::vector<DerivativeArrow> arrow_data;
    // A GB face's free points: positions [free_first, free_first + free_count), face `face`.
    int face = -1;
    std::size_t free_first = 0, free_count = 0;
  };
  std::vector<Group> groups;
  std::vector<int> face_group;   // per surface: its group, or -1 (explicit pieces)
  std::vector<int> patch_group;  // per scene patch: its group

  // Points left out of the drawing where they would cover the surface (net_thinning.hpp): not
  // drawn and not picked. Empty: every point is shown.
  std::vector<uint8_t> hidden;
  bool shown(std::size_t i) const { return hidden.empty() || !hidden[i]; }

  std::vector<bool> editable() const;
  int find(const PointRef& ref) const;  // index of ref, or -1
};

// `filling` (the evaluation's, in step with `scene`) gives the topology and tangent planes the
// free points' defaults are built from; without it they are built here.
ScenePoints collect_scene_points(const Scene& scene, const SceneSurfaces& surfaces,
                                 const IncrementalFilling* filling = nullptr);

// Refreshes group g's positions and arrows from `patch` (the same patch type and size as when
// collected). Returns false when the patch no longer matches the group.
bool update_group(ScenePoints& points, std::size_t g, const Patch& patch);
// Refreshes group g's free points (defaults from the filling, offsets from the scene) at the cost
// of that face (`cross`: scratch kept by the caller). Returns false when the face's free points
// are no longer those listed.
bool update_free_points(ScenePoints& points, std::size_t g, const Scene& scene, const Patch& patch,
                        const IncrementalFilling& filling, std::vector<EdgeCrossTangents>& cross);

// The net the renderer draws from the points: every point with its kind and role (derived where
// there is no ref), the segments and the arrows; with `only_shown`, the shown points only (and
// the segments between them). `out` keeps its capacity.
void make_control_net(const ScenePoints& points, bool only_shown, ControlNet& out);

// The overlays of a DrawScene from the points: the net, the arrows and the network curves.
// Borders and curvature combs are LiveCurves'.
void fill_overlays(const Scene& scene, const ScenePoints& points, DrawScene& draw);

}  // namespace pl
