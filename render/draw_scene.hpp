// Everything the renderer draws, as plain arrays (architecture: "the renderer eats plain
// arrays"): tessellated surfaces with exact normals and curvatures, the control net with the kind
// of every point, polylines for network curves and patch borders, and their curvature combs. The
// app builds it from a scene; the renderer never sees patch classes.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/curve/curvature_comb.hpp"
#include "core/mesh/surface_mesh.hpp"
#include "core/patch/patch.hpp"  // ControlPointKind only
#include "render/camera.hpp"

namespace pl {

struct ControlNet {
  std::vector<Vec3> points;
  std::vector<ControlPointKind> kinds;            // one per point
  std::vector<std::array<uint32_t, 2>> segments;  // indices into points
};

using Polyline = std::vector<Vec3>;

struct DrawScene {
  std::vector<SurfaceMesh> surfaces;
  ControlNet net;
  std::vector<Polyline> network_curves;
  std::vector<Polyline> borders;
  // Curvature combs (plain arrays: sample points and teeth) of the network curves and of the
  // borders, drawn on the curves that are shown when the `combs` overlay is on.
  std::vector<CurvatureComb> network_combs;
  std::vector<CurvatureComb> border_combs;
  // Per border comb: true for a side of a network face, whose comb is its edge's. With both
  // overlays on, only the network's is drawn (twice would double the alpha and the cost).
  std::vector<bool> border_on_network;

  // Of the surfaces, net and curves: what a camera frames.
  Box bounds() const;
};

}  // namespace pl
