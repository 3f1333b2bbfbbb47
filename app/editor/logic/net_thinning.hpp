// Which control points are worth drawing at the size the network has on screen. A 1,536-face
// network seen whole puts tens of thousands of points on a few hundred thousand pixels: they
// cover the surface, say nothing, and on a CPU rasteriser cost more than the surfaces (110 ms a
// frame). So points are drawn only when they would stand kNetPointSpacing point widths apart:
//   - the faces' derived points when, on the median face, they would (a face's n points are
//     about its diameter / (sqrt(n) + 1) apart);
//   - the handles when they would on the median edge (an edge is three handle spacings long);
//   - the vertices when the median vertex's shortest edge is long enough;
//   - an explicit patch's points by the patch's own size (scenes hold a few, of any size).
// Network points go as a whole, by the median: decided per object, those near the threshold
// would come and go in a ragged pattern.
// and whatever the size, the objects in focus (selected, under the cursor, being dragged) show
// their points: a selected face its whole net, a vertex its handles, an edge its vertices and
// handles. Hidden points are neither drawn nor picked. GUI-free.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "app/editor/logic/scene_points.hpp"

namespace pl {

// Points closer than this many point widths on screen are not told apart.
inline constexpr double kNetPointSpacing = 1.5;

struct NetScreenSizes {
  std::vector<double> edge_pixels;     // per network edge: its length on screen
  std::vector<double> surface_pixels;  // per surface: its diameter on screen
};

// The objects whose points are shown whatever their size.
struct NetFocus {
  std::vector<int> vertices, edges, faces, patches;  // network and scene patch indices
  bool operator==(const NetFocus&) const = default;
};

struct NetThinning {
  std::vector<uint8_t> hidden;  // per point of the ScenePoints; empty when every point is shown
  std::size_t hidden_vertices = 0, hidden_handles = 0, hidden_derived = 0, hidden_patch = 0,
              hidden_free = 0;  // free interior points of GB faces
  // For the status bar: what is hidden and why; empty when nothing is.
  std::string note() const;
};

// `surfaces` is the evaluation the points were collected from (its faces), `network` the
// scene's (or null); point_px the width of a drawn point in pixels.
NetThinning thin_control_net(const ScenePoints& points, const SceneSurfaces& surfaces,
                             const Network* network, const NetScreenSizes& sizes,
                             const NetFocus& focus, double point_px);

// The focus of a selection and hover: the editable points they name (vertices, handles' edges,
// patch points' patches) and the faces, edges and patches themselves.
NetFocus net_focus(const std::vector<PointRef>& points, const std::vector<int>& edges,
                   const std::vector<int>& faces, const std::vector<int>& patches);

}  // namespace pl
