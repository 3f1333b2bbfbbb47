// Everything the renderer draws, as plain arrays (the renderer eats plain arrays): tessellated
// surfaces with exact normals and curvatures, the control net with the kind and role of every
// point, derivative data as arrows, polylines for network curves and patch borders, their
// curvature combs, and highlighted curves. The app builds it from a scene; the renderer never sees
// patch classes.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/curve/curvature_comb.hpp"
#include "core/mesh/surface_mesh.hpp"
#include "core/patch/control_net_topology.hpp"  // ArrowKind
#include "core/patch/patch.hpp"                 // ControlPointKind
#include "render/camera.hpp"

namespace pl {

// Who moves a point: editable points (network vertices and handles, explicit patch points) are
// drawn filled and on top; derived ones (Gregory twins, GB ribbon rows of network faces) hollow,
// smaller and underneath, so an editable point is never hidden by a derived one at its place.
enum class PointRole : uint8_t { Editable, Derived };

struct ControlNet {
  std::vector<Vec3> points;
  std::vector<ControlPointKind> kinds;  // one per point: the shape and colour
  std::vector<PointRole> roles;         // one per point, or empty: every point editable
  // Indices into points; a segment touching a derived point is drawn as a derived line.
  std::vector<std::array<uint32_t, 2>> segments;

  PointRole role(std::size_t i) const { return i < roles.size() ? roles[i] : PointRole::Editable; }
};

// A derivative vector drawn from the point it belongs to (core/patch/control_net_topology.hpp
// gives the tip: the equivalent Bézier handle).
struct Arrow {
  Vec3 base, tip;
  ArrowKind kind = ArrowKind::Tangent;
};

// Room for this many point kinds in a style tag (the shader reads kind = tag % 8).
inline constexpr int kPointStyleKinds = 8;
// The tag of a point's style in the shaders and keys: kind + kPointStyleKinds * role.
inline int point_style_tag(ControlPointKind kind, PointRole role) {
  return static_cast<int>(kind) + kPointStyleKinds * static_cast<int>(role);
}

// Which point styles (bit point_style_tag) a net has, and which arrow kinds (bit ArrowKind): the
// entries of its key (render/point_key.hpp).
uint32_t point_style_bits(const ControlNet& net);
uint32_t arrow_kind_bits(const std::vector<Arrow>& arrows);

using Polyline = std::vector<Vec3>;

// The sign of the volume the meshes' triangles enclose: +1 (normals outward), -1 (inward), 0
// when it is too small to tell (flat or degenerate). Meaningful for closed meshes.
int enclosed_volume_sign(const std::vector<SurfaceMesh>& meshes);

struct DrawScene {
  std::vector<SurfaceMesh> surfaces;
  ControlNet net;
  std::vector<Arrow> arrows;  // drawn with the control net
  std::vector<Polyline> network_curves;
  std::vector<Polyline> borders;
  // Curvature combs (plain arrays: sample points and teeth) of the network curves and of the
  // borders, drawn on the curves that are shown when the `combs` overlay is on.
  std::vector<CurvatureComb> network_combs;
  std::vector<CurvatureComb> border_combs;
  // Per border comb: true for a side of a network face, whose comb is its edge's. With both
  // overlays on, only the network's is drawn (twice would double the alpha and the cost).
  std::vector<bool> border_on_network;
  // Free curves of the scene (always drawn) and their combs (drawn with the `combs` overlay).
  std::vector<Polyline> free_curves;
  std::vector<CurvatureComb> free_curve_combs;
  // Drawn on top of everything in palette::kHighlight (e.g. the edge a panel points at).
  std::vector<Polyline> highlights;
  // The surfaces bound a solid (a closed network, consistently oriented): +1 with their normals
  // outward, -1 inward; 0 when they do not (or it is not known). Seen from outside, a solid's
  // inner side is hidden by its outer side, so the renderer skips it (half the triangles).
  int closed_orientation = 0;

  // Of the surfaces, net and curves: what a camera frames.
  Box bounds() const;
};

}  // namespace pl
