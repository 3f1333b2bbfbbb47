#include "app/editor/logic/transform_selection.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

#include "app/document/transform_command.hpp"
#include "app/editor/logic/editor_model.hpp"
#include "app/editor/logic/selection_properties.hpp"
#include "app/editor/logic/tool.hpp"

namespace pl {

std::vector<PointRef> transform_points(const Scene& scene, const Selection& selection) {
  std::vector<PointRef> points = points_of(scene, selection);
  for (const SelectionItem& item : selection.items()) {
    if (item.kind != SelectionItem::Kind::Face || !item_exists(scene, item)) continue;
    for (const InteriorOffset& o : scene.network->faces[item.index].offsets) {
      const PointRef r = PointRef::free_point(item.index, o);
      if (std::find(points.begin(), points.end(), r) == points.end()) points.push_back(r);
    }
  }
  return points;
}

SimilarityOrError similarity_for(const TransformRequest& r, const Scene& scene,
                                 const std::vector<PointRef>& points, const Vec3& work_plane_point,
                                 const Vec3& work_plane_normal) {
  if (points.empty()) return {std::nullopt, "nothing selected to transform"};
  Vec3 pivot(0);
  switch (r.pivot) {
    case PivotKind::SelectionCentre:
      for (const PointRef& p : points) pivot += point_position(scene, p);
      pivot /= double(points.size());
      break;
    case PivotKind::Vertex:
      if (!scene.network || r.pivot_vertex < 0 ||
          r.pivot_vertex >= static_cast<int>(scene.network->vertices.size()))
        return {std::nullopt, "no vertex " + std::to_string(r.pivot_vertex) + " to turn about"};
      pivot = scene.network->vertices[r.pivot_vertex];
      break;
    case PivotKind::Origin:
      break;
    case PivotKind::WorkPlanePoint:
      pivot = work_plane_point;
      break;
  }
  Similarity t;
  switch (r.kind) {
    case TransformKind::Move:
      if (!finite(r.offset)) return {std::nullopt, "the move is not a finite vector"};
      t = Similarity::translation(r.offset);
      break;
    case TransformKind::Rotate: {
      if (!std::isfinite(r.angle_deg)) return {std::nullopt, "the angle is not a number"};
      const Vec3 axis = r.axis == AxisKind::X   ? Vec3(1, 0, 0)
                        : r.axis == AxisKind::Y ? Vec3(0, 1, 0)
                        : r.axis == AxisKind::Z ? Vec3(0, 0, 1)
                                                : work_plane_normal;
      t = Similarity::rotation_about(pivot, axis, r.angle_deg * M_PI / 180);
      break;
    }
    case TransformKind::Scale:
      if (!std::isfinite(r.factor) || !(r.factor > 0))
        return {std::nullopt, "a scale factor must be a positive number"};
      t = Similarity::scaling(pivot, r.factor);
      break;
  }
  return {t, {}};
}

bool transform_selection(EditorModel& model, const TransformRequest& request) {
  const Scene& scene = model.doc().scene();
  const std::vector<PointRef> points = transform_points(scene, model.selection());
  const Camera& camera = model.nav().camera();
  const PlaneFrame plane = model.work_plane().frame(camera);
  const SimilarityOrError t = similarity_for(request, scene, points, plane.origin, plane.normal);
  if (!t.similarity) {
    model.status().say("cannot transform: " + t.error);
    return false;
  }
  return run_command(
      model.doc(), [&model](const std::string& s) { model.status().say(s); },
      std::make_shared<TransformPointsCommand>(points, *t.similarity));
}

}  // namespace pl
