// The tangent planes of the selected network vertices as the view shows them: a disc in the
// plane at the vertex and a normal handle (a line from the vertex along the normal, ending in a
// knob) that the designer drags to turn the plane. Sizes are in pixels, so the handles look the
// same at any zoom. GUI-free and unit-tested: the select tool picks and drags the knob, the
// overlay draws the disc and the handle from the same PlaneHandle.
#pragma once

#include <optional>
#include <vector>

#include "app/editor/logic/selection.hpp"
#include "app/editor/logic/view_math.hpp"

namespace pl {

struct VertexPlane {
  Vec3 normal{0, 0, 1};  // unit
  bool fixed = false;    // a normal is stored; else the plane is fitted to the edges
};

// The plane the handles at v are kept in (handle_plane_normal), or for a vertex with two edges
// the plane their end tangents span (the plane a fixed normal would turn); oriented like the
// faces at v (right-hand rule) when v has any, else as found. nullopt when v has no plane:
// no fixed normal and fewer than two edges, or collinear tangents.
std::optional<VertexPlane> vertex_plane(const Network& network, int v);

// Pixel sizes of the handle, before the interface scale.
inline constexpr double kPlaneDiscRadiusPx = 30;
inline constexpr double kNormalHandlePx = 62;
inline constexpr double kKnobPickRadiusPx = 9;
// At most this many selected vertices show their planes (a select-all shows none).
inline constexpr std::size_t kMaxPlaneHandles = 12;

struct PlaneHandle {
  int vertex = -1;
  Vec3 centre{0.0};
  Vec3 normal{0, 0, 1};  // unit
  bool fixed = false;
  double radius = 0;  // of the disc, world units
  Vec3 knob{0.0};     // the end of the normal handle
};

// The handles of the selected network vertices that have a plane, in selection order.
std::vector<PlaneHandle> plane_handles(const Scene& scene, const Selection& selection,
                                       const Camera& camera, const ViewRect& rect, double ui_scale);

// The handle whose knob is nearest `pixel` within `radius_px`, or -1.
int pick_knob(const std::vector<PlaneHandle>& handles, const Camera& camera, const ViewRect& rect,
              const Vec2& pixel, double radius_px);

// The normal while the knob is dragged: the knob follows the cursor in the view plane through it
// (`motion` holds the knob's start and the press pixel); the normal points from the vertex to
// it. nullopt when the cursor puts the knob on the vertex.
std::optional<Vec3> dragged_normal(const PlaneHandle& handle, const DragMotion& motion,
                                   const Camera& camera, const ViewRect& rect, const Vec2& pixel);

}  // namespace pl
