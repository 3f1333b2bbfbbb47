// The connectivity a designer reads in a control net, per patch family: which control points are
// joined by net lines (rows and columns of grids, GB rows and spokes, Gregory ribbons and twin
// pairs, the Catmull–Clark cage) and which entries are derivative vectors rather than positions
// (Hermite tangents and twists, Coons network derivatives), drawn as arrows from the position they
// belong to. Indices are the patch's own control point indices; GL-free, used by whoever draws.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/patch/patch.hpp"

namespace pl {

class BezierPatch;
class BSplinePatch;
class NurbsPatch;
class InterpolatingPatch;
class HermitePatch;
class CoonsNetworkPatch;
class GregoryQuadPatch;
class GregoryTriPatch;
class GBPatch;
class GBRibbonPatch;
class GBInteriorPatch;
class CatmullClarkPatch;
class PairJoinPatch;
class GapFillPatch;
class RibbonPatch;

enum class ArrowKind { Tangent, Twist };

// A derivative entry drawn as an arrow from base to base + scale * vector. The scale makes the
// arrow the equivalent Bézier handle: a cubic Hermite tangent r' spans r'/3 to the next Bézier
// point and a twist r_uv contributes r_uv/9 to the inner point, so arrows are comparable with the
// nets of the other patch types and an editor can drag the tip (vector = (tip - base) / scale).
struct DerivativeArrow {
  uint32_t base = 0;    // control point index of the position
  uint32_t vector = 0;  // control point index of the derivative
  double scale = 1;     // > 0
  ArrowKind kind = ArrowKind::Tangent;
};

struct ControlNetTopology {
  // Net lines between positions (never vectors), each pair once, smaller index first.
  std::vector<std::array<uint32_t, 2>> segments;
  std::vector<DerivativeArrow> arrows;
  // Per control point: true for an entry that is not a position of the net: a derivative vector,
  // drawn only as its arrow, or a hidden entry that is not drawn at all (a network GB face's
  // default filling and free-point defaults behind its degree-d net). Same size as the patch.
  std::vector<bool> is_vector;
};

// The net of any patch (dispatches on the type below). A type without a net (none today) gets no
// segments; every point is then a position.
ControlNetTopology control_net_topology(const Patch& patch);

// Where an arrow's tip is drawn.
Vec3 arrow_tip(const Patch& patch, const DerivativeArrow& arrow);

// Per family. Grids (i * nv + j) give their rows and columns.
std::vector<std::array<uint32_t, 2>> grid_segments(std::size_t nu, std::size_t nv,
                                                   uint32_t first = 0);
ControlNetTopology bezier_net(const BezierPatch& p);
ControlNetTopology spline_net(const BSplinePatch& p);
ControlNetTopology spline_net(const NurbsPatch& p);
ControlNetTopology interpolating_net(const InterpolatingPatch& p);
ControlNetTopology pair_join_net(const PairJoinPatch& p);  // the auxiliary patch's grid
ControlNetTopology gap_fill_net(const GapFillPatch& p);    // q's grid and r's grid
// The four corner points as a quadrilateral; tangents and twists as arrows.
ControlNetTopology hermite_net(const HermitePatch& p);
// The grid of node positions; r_s, r_t, r_st as arrows, scaled by the node's mean parameter
// spacing along its row (column) so that they are the handles of the boundary cubics.
ControlNetTopology coons_network_net(const CoonsNetworkPatch& p);
// Per side: the boundary row, the inner row through its two twins and the lines from the twins
// to the boundary points they pull on; at every corner, the pair of twins that split one
// Bézier point.
ControlNetTopology gregory_net(const GregoryQuadPatch& p);
ControlNetTopology gregory_net(const GregoryTriPatch& p);
// Per ribbon: rows (parallel to the side) and spokes (towards the centre) of its (d+1) x l grid,
// shared corner blocks once; the central point is joined to the middle of the innermost row.
ControlNetTopology gb_net(const GBPatch& p);
// A network GB face with interior control: its degree-d net drawn as gb_net draws a .gbp net; the
// entries after the net (the default filling's points, the free points' defaults) hidden.
ControlNetTopology gb_interior_net(const GBInteriorPatch& p);
// Per ribbon: the rows and spokes of its grid.
ControlNetTopology gb_ribbon_net(const GBRibbonPatch& p);
// The base mesh's edges (the cage).
ControlNetTopology catmull_clark_net(const CatmullClarkPatch& p);
// Each side's curve a polyline; the cross derivatives' control vectors arrows from the curve's
// points to the ribbon's inner Bézier row where curve and cross derivative share one Bézier
// degree, else hidden.
ControlNetTopology ribbon_net(const RibbonPatch& p);

}  // namespace pl
