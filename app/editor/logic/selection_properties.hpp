// The properties the selection panel shows for one selected object, read from the scene:
// face (sides, stored and resolved scheme, name), edge (name, ends, length, faces using it),
// vertex (tangent plane fitted or fixed, edges at it), edge handle, explicit patch. GUI-free and
// unit-tested; the panel only lays the fields out.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "app/editor/logic/selection.hpp"
#include "core/curve/bezier_curve.hpp"
#include "render/camera.hpp"

namespace pl {

struct FaceProperties {
  int face = -1;
  std::string name;
  int sides = 0;
  FaceScheme scheme = FaceScheme::Auto;  // as stored
  FaceScheme resolved = FaceScheme::GB;  // what it is filled with
  bool gregory_allowed = false;          // 3 or 4 sides
};

struct EdgeProperties {
  int edge = -1;
  std::string name;
  int from = -1, to = -1;  // vertices
  double length = 0;       // of the cubic curve
  std::vector<int> faces;  // faces with this edge as a side (0, 1 or 2)
};

struct VertexProperties {
  int vertex = -1;
  Vec3 position{0.0};
  bool tangent_plane_fixed = false;  // a normal is stored; else the plane is fitted
  std::optional<Vec3> normal;        // the stored normal when fixed
  int edges = 0;                     // valence
};

struct PatchProperties {
  int patch = -1;
  std::string name;
  std::string type;  // the file format's type name
  int points = 0;
};

// nullopt when the item is of another kind or no longer exists.
std::optional<FaceProperties> face_properties(const Scene& scene, int face);
std::optional<EdgeProperties> edge_properties(const Scene& scene, int edge);
std::optional<VertexProperties> vertex_properties(const Scene& scene, int vertex);
std::optional<PatchProperties> patch_properties(const Scene& scene, int patch);

// Arc length of a curve: Gauss-Legendre quadrature of |C'(t)| on subintervals, refined until two
// successive results agree to `relative_tolerance` (the integrand is smooth: a polynomial
// under a square root).
double curve_length(const BezierCurve& curve, double relative_tolerance = 1e-12);

const char* scheme_name(FaceScheme scheme);  // "Auto", "Gregory", "GB"

// The edges of each face's sides, in side order (-1 where no edge joins the two vertices).
std::vector<std::vector<int>> face_edges(const Network& network, const std::vector<int>& faces);

// The editable points of the selected objects: points themselves, an edge's vertices and
// handles, a face's vertices and the handles of its edges, a patch's control points. No
// duplicates, in selection order.
std::vector<PointRef> points_of(const Scene& scene, const Selection& selection);

// The box around the selected objects (their points, and the curves of edges and faces, which
// lie in their control polygons' hull); empty when nothing selected exists.
Box selection_bounds(const Scene& scene, const Selection& selection);

}  // namespace pl
