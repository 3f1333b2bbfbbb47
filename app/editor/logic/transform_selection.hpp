// Move, rotate and scale the selection by typed values about a chosen pivot: what the Selection
// panel's Transform rows ask for, as one undo step (TransformPointsCommand). GUI-free.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "app/document/point_ref.hpp"
#include "core/math/similarity.hpp"

namespace pl {

class EditorModel;
class Selection;

enum class TransformKind { Move, Rotate, Scale };
enum class PivotKind { SelectionCentre, Vertex, Origin, WorkPlanePoint };
enum class AxisKind { X, Y, Z, WorkPlaneNormal };

struct TransformRequest {
  TransformKind kind = TransformKind::Rotate;
  PivotKind pivot = PivotKind::SelectionCentre;
  int pivot_vertex = -1;  // PivotKind::Vertex
  AxisKind axis = AxisKind::Z;
  double angle_deg = 0;  // Rotate: right-handed about the axis
  double factor = 1;     // Scale: uniform, > 0
  Vec3 offset{0};        // Move
};

// The points a transform of the selection moves: its editable points (points_of) and the moved
// interior points of its GB faces (their offsets turn and scale with the face).
std::vector<PointRef> transform_points(const Scene& scene, const Selection& selection);

// The similarity a request means for `points` of `scene` (the pivot read from the scene or the
// work plane), or an error message (no points, a missing pivot vertex, a zero or non-finite
// factor, a non-finite value).
struct SimilarityOrError {
  std::optional<Similarity> similarity;
  std::string error;
};
SimilarityOrError similarity_for(const TransformRequest& request, const Scene& scene,
                                 const std::vector<PointRef>& points, const Vec3& work_plane_point,
                                 const Vec3& work_plane_normal);

// Runs the request on the model's selection (one undo step); the status line says what was done
// or why not. Returns whether the document changed.
bool transform_selection(EditorModel& model, const TransformRequest& request);

}  // namespace pl
