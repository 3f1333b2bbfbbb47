// Turns an evaluated scene into the renderer's plain arrays (render/draw_scene.hpp): meshes with
// exact normals and curvatures, the control net with point kinds, network curves and patch
// borders with their curvature combs (comb_teeth tooth intervals per curve). GL-free: the `render`
// command and the editor share it, and the drawing code never sees patch classes. The curve
// helpers below serve the editor too.
#pragma once

#include <array>
#include <map>
#include <span>

#include "core/eval/scene_surfaces.hpp"
#include "core/scene/scene.hpp"
#include "render/display_settings.hpp"
#include "render/draw_scene.hpp"

namespace pl {

// comb_teeth 0: no combs (borders without teeth, no network combs). The net has every patch's
// connectivity (core/patch/control_net_topology.hpp), derivative data as arrows, and the points
// of network faces as derived.
DrawScene build_draw_scene(const Scene& scene, const SceneSurfaces& surfaces,
                           int comb_teeth = DisplaySettings().comb_teeth);

// DrawScene::closed_orientation of an evaluated scene: a network alone whose every edge joins
// two faces (validation makes shared edges run opposite ways: a consistent orientation) bounds
// a solid; which side its normals face is the sign of the volume its meshes enclose.
int closed_orientation(const Scene& scene, const SceneSurfaces& surfaces,
                       const std::vector<SurfaceMesh>& meshes);

// Appends one patch's control net to d: its positions as points of `role` (kinds from the patch),
// its net lines and its derivative arrows. With `shared`, a position found there exactly (the
// network's vertices and handles) is that point instead of a new one.
void append_patch_net(DrawScene& d, const Patch& patch, PointRole role,
                      const std::map<std::array<double, 3>, uint32_t>* shared = nullptr);

// Segments of the polyline drawn for a network curve or a border without a comb: smooth at
// 4096 px for the cubic edges we draw, and as many as a comb's envelope has at least.
inline constexpr int kCurveSegments = kMinCombEnvelopeSegments;

// Every network edge curve as a polyline of kCurveSegments segments.
std::vector<Polyline> network_polylines(const Network& network);
// Network edge e's polyline (one entry of network_polylines, or with fewer segments for an edge
// that is small on screen).
Polyline edge_polyline(const Network& network, int e, int segments = kCurveSegments);
// A curve at t = k / segments, k = 0..segments.
Polyline curve_polyline(const BezierCurve& curve, int segments);
// Every network edge's curvature comb (comb_teeth >= 1).
std::vector<CurvatureComb> network_combs(const Network& network, int comb_teeth);

// A free curve as drawn: every span sampled uniformly (at least kCurveSegments segments in all),
// and its curvature comb, one comb per span (comb_teeth tooth intervals each).
// The samples per span a free curve is drawn with (about kCurveSegments in all, 8 at least).
int free_curve_samples_per_span(const SceneCurve& curve);
Polyline free_curve_polyline(const SceneCurve& curve);
// The same at per_span samples per span.
Polyline free_curve_polyline(const SceneCurve& curve, int per_span);
// The segments the free curves of one picture are drawn with, in all, before their sizes are
// looked at: past it (thousands of curves or spans) a curve gets about one segment per 2 pixels
// of the longest picture it can take (its control polygon's length over the curves' size, times
// the 4096 x 4096 picture's diagonal), one per span at least and never more than its own count:
// the drawing's cost follows the length drawn and the number of spans, and llvmpipe no longer
// rasterises 64 segments of a curve less than a pixel long.
inline constexpr std::size_t kFreeCurveSegmentBudget = std::size_t(1) << 16;
// The samples per span of each of these curves (free_curve_samples_per_span, or the reduced
// count above when their sum is over kFreeCurveSegmentBudget).
std::vector<int> free_curves_samples_per_span(std::span<const SceneCurve> curves);
std::vector<CurvatureComb> free_curve_combs(const SceneCurve& curve, int comb_teeth);
// The comb of one span [t0, t1] of the curve (one of free_curve_combs).
CurvatureComb free_curve_span_comb(const SceneCurve& curve, std::pair<double, double> span,
                                   int comb_teeth);
// The curve, its comb (comb_teeth > 0) and its control polygon appended to d.
void append_free_curve(DrawScene& d, const SceneCurve& curve, int comb_teeth);
// The same with the polyline at per_span samples per span.
void append_free_curve(DrawScene& d, const SceneCurve& curve, int comb_teeth, int per_span);

// One per domain side of the surface, from the surface jet along the side (exact for every patch
// type; boundary_curves() only approximates some types' sides): the points are the border drawn,
// the teeth its comb. comb_teeth 0: the points alone (kCurveSegments segments), no teeth.
std::vector<CurvatureComb> surface_borders(const SceneSurface& surface, int comb_teeth);

}  // namespace pl
