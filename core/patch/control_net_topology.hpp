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

// The net of any registered patch type: its net_of overload below, chosen through
// visit_patch_type (patch_types.hpp), which has no default, so every type has its own net.
ControlNetTopology control_net_topology(const Patch& patch);

// Where an arrow's tip is drawn.
Vec3 arrow_tip(const Patch& patch, const DerivativeArrow& arrow);

// Per type. Grids (i * nv + j) give their rows and columns.
std::vector<std::array<uint32_t, 2>> grid_segments(std::size_t nu, std::size_t nv,
                                                   uint32_t first = 0);
ControlNetTopology net_of(const BezierPatch& p);
ControlNetTopology net_of(const BSplinePatch& p);
ControlNetTopology net_of(const NurbsPatch& p);
ControlNetTopology net_of(const InterpolatingPatch& p);
ControlNetTopology net_of(const PairJoinPatch& p);  // the auxiliary patch's grid
ControlNetTopology net_of(const GapFillPatch& p);   // q's grid and r's grid
// The four corner points as a quadrilateral; tangents and twists as arrows.
ControlNetTopology net_of(const HermitePatch& p);
// The grid of node positions; r_s, r_t, r_st as arrows, scaled by the node's mean parameter
// spacing along its row (column) so that they are the handles of the boundary cubics.
ControlNetTopology net_of(const CoonsNetworkPatch& p);
// Per side: the boundary row, the inner row through its two twins and the lines from the twins
// to the boundary points they pull on; at every corner, the pair of twins that split one
// Bézier point.
ControlNetTopology net_of(const GregoryQuadPatch& p);
ControlNetTopology net_of(const GregoryTriPatch& p);
// Per ribbon: rows (parallel to the side) and spokes (towards the centre) of its (d+1) x l grid,
// shared corner blocks once; the central point is joined to the middle of the innermost row.
ControlNetTopology net_of(const GBPatch& p);
// A network GB face with interior control: its degree-d net, drawn as a GBPatch's net; the
// entries after the net (the default filling's points, the free points' defaults) hidden.
ControlNetTopology net_of(const GBInteriorPatch& p);
// Per ribbon: the rows and spokes of its grid.
ControlNetTopology net_of(const GBRibbonPatch& p);
// The base mesh's edges (the cage).
ControlNetTopology net_of(const CatmullClarkPatch& p);
// Each side's curve a polyline; the cross derivatives' control vectors arrows from the curve's
// points to the ribbon's inner Bézier row where curve and cross derivative share one Bézier
// degree, else hidden.
ControlNetTopology net_of(const RibbonPatch& p);

}  // namespace pl
