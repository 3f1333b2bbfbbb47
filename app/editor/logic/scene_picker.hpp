// What lies under the cursor in a view: a control point (drawn over everything, so picked
// within a pixel radius whatever its depth; editable points before derived ones, and those in
// front of the surface under the cursor before those behind it), else the nearest network curve
// or free curve (within a pixel radius and not hidden behind a surface), else the nearest
// surface along the ray. A click selects the first of these that is selectable: the point, the
// curve's edge or the free curve, or the surface's face (or explicit patch).
//
// Surfaces are cast against exactly the triangles drawn, through two levels of bounding
// volumes: every surface's box (kept per mesh revision, so an edit re-boxes only the surfaces it
// changed) and, for the few surfaces whose box the ray enters, a TriangleBvh built on first use.
// Boxes are visited nearest first and a hit closer than the next box's entry ends the search.
// GUI-free and unit-tested.
#pragma once

#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "app/editor/logic/scene_points.hpp"
#include "app/editor/logic/selection.hpp"
#include "app/editor/logic/triangle_bvh.hpp"
#include "core/eval/scene_surfaces.hpp"
#include "core/mesh/surface_mesh.hpp"

namespace pl {

// What a view shows, as the picker reads it.
struct PickScene {
  std::span<const SurfaceMesh> meshes;
  std::span<const SelectionItem> surface_items;  // per mesh: its face or explicit patch
  std::span<const Polyline> curves;              // per network edge (empty: no network)
  const ScenePoints* points = nullptr;           // null: no points
  std::span<const Polyline> free_curves;         // per scene curve (always shown)
};

// Per surface of an evaluation: the face it fills, or the explicit patch it draws.
std::vector<SelectionItem> surface_items(const SceneSurfaces& surfaces);

struct PickOptions {
  bool points = true;  // control points are shown
  bool curves = true;  // network curves are shown
  double point_radius_px = 9.0;
  double curve_radius_px = 6.0;
};

struct SurfaceHit {
  int surface = -1;
  TriangleHit hit;
  Vec3 position{0.0};
};

struct PickResult {
  std::optional<SelectionItem> item;  // what a click here selects
  int point = -1;                     // ScenePoints index under the cursor, -1 if none
  bool derived_point = false;         // that point is derived (shown, not editable)
  int edge = -1;                      // network edge under the cursor, -1 if none
  // Where on that edge: its curve parameter (the polylines sample the curve at even steps of t,
  // so this is exact at the samples and linear between them).
  double edge_t = 0;
  int curve = -1;         // free curve under the cursor (nearer than any edge), -1 if none
  Vec3 curve_point{0.0};  // the point of its drawn line nearest the cursor
  std::optional<SurfaceHit> surface;  // nearest surface along the ray
};

class ScenePicker {
 public:
  PickResult pick(const PickScene& scene, const Camera& camera, const ViewRect& rect,
                  const Vec2& pixel, const PickOptions& options = {});
  // The nearest surface hit along the ray.
  std::optional<SurfaceHit> cast(std::span<const SurfaceMesh> meshes, const Ray& ray);

  // Forgets every cached box and hierarchy (a new document).
  void reset() { cache_.clear(); }

  struct Stats {
    std::size_t surfaces = 0;      // cached boxes
    std::size_t hierarchies = 0;   // built TriangleBvh
    std::size_t memory_bytes = 0;  // of those hierarchies
  };
  Stats stats() const;

 private:
  struct Entry {
    const SurfaceMesh* mesh = nullptr;
    uint64_t revision = 0;
    std::size_t vertices = 0, triangles = 0;
    Box box;
    std::unique_ptr<TriangleBvh> bvh;  // built when a ray first enters the box
  };
  void refresh(std::span<const SurfaceMesh> meshes);
  std::vector<Entry> cache_;
};

// A window pixel where a click selects `item` (a face, patch, edge or free curve): over the
// face's surface or on the edge's (or free curve's) line, with no point under the cursor, nearest
// to the middle of what is visible of it. nullopt when nothing of it can be clicked in this view.
// Scripts and the end-to-end test use it to click a face like a user would.
std::optional<Vec2> find_pixel_for(ScenePicker& picker, const PickScene& scene,
                                   const Camera& camera, const ViewRect& rect,
                                   const SelectionItem& item, const PickOptions& options = {});

}  // namespace pl
