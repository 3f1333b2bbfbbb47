// The curve network of scene-format.md: cubic Bézier edges meeting at vertices; faces are closed
// loops of edges. Face side i runs from loop[i] to loop[i+1] (indices mod n) along the edge that
// joins them, traversed forwards or backwards.
#pragma once

#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/curve/bezier_curve.hpp"

namespace pl {

// How a face is filled: Auto (Gregory for 3 and 4 sides, GB otherwise), the Gregory and GB
// patches of the Chiyokura-Kimura ribbons, or one of the ribbon-based transfinite schemes over
// the same ribbons (core/patch/transfinite). The keywords, the list of all schemes and the
// parsing live in one place: core/scene/network_edit.hpp (scheme_keyword, all_face_schemes).
enum class FaceScheme {
  Auto,
  Gregory,
  GB,
  SideBased,
  CornerBased,
  GeneralizedCoons,
  CompositeRibbon,
  Midpoint,
  MidpointCoons,
  Elastic
};

struct NetworkEdge {
  std::array<int, 2> v{0, 0};  // start and end vertex
  std::array<Vec3, 2> handles{Vec3(0), Vec3(0)};
  std::string name;
  bool operator==(const NetworkEdge&) const = default;
};

// A displacement of one free interior control point of a GB face from its default position
// (docs/scene-format.md, "Interior control"): the central point, or point j of layer k of the
// ribbon on face side i in the .gbp naming (a shared corner-block point may be named from either
// ribbon).
struct InteriorOffset {
  bool centre = false;
  int side = 0, j = 0, layer = 0;  // when !centre
  Vec3 by{0};
  bool operator==(const InteriorOffset&) const = default;
};

struct NetworkFace {
  // A constructor (not an aggregate) so that {loop, scheme, name} stays the short form.
  NetworkFace() = default;
  NetworkFace(std::vector<int> loop_, FaceScheme scheme_ = FaceScheme::Auto, std::string name_ = {})
      : loop(std::move(loop_)), scheme(scheme_), name(std::move(name_)) {}
  std::vector<int> loop;
  FaceScheme scheme = FaceScheme::Auto;
  std::string name;
  int degree = 3;  // GB faces: the degree of every ribbon along its side (>= 3)
  std::vector<InteriorOffset> offsets;  // GB faces: the free points moved from their defaults
  // Midpoint schemes: the fullness of the face (1: the schemes' default midpoint; see
  // RibbonPatchOptions::fullness and docs/scene-format.md).
  double fullness = 1;
  bool operator==(const NetworkFace&) const = default;
};

struct Network {
  std::vector<Vec3> vertices;
  std::vector<std::optional<Vec3>> normals;  // empty, or one per vertex
  std::vector<NetworkEdge> edges;
  std::vector<NetworkFace> faces;

  // The cubic edge e with control points vertex a, h1, h2, vertex b.
  BezierCurve edge_curve(int e) const;
  bool operator==(const Network&) const = default;
};

// How face sides use edges; computed by validate_network.
struct FaceSide {
  int edge = -1;
  bool reversed = false;  // the side runs from edge end to edge start
};
struct EdgeUse {
  int face = -1, side = -1;
};
struct NetworkTopology {
  std::vector<std::vector<FaceSide>> face_sides;  // [face][side]
  std::vector<std::vector<EdgeUse>> edge_faces;   // [edge]: 0, 1 or 2 uses
  std::vector<std::vector<int>> vertex_edges;     // [vertex]: incident edges
};

// The network's adjacency: which edge joins two vertices, whichever way round. The one rule by
// which a face loop's consecutive vertices name its edges; validate_network, the authoring edits
// (network_edit.hpp) and the sample networks all look edges up here.
class EdgeIndex {
 public:
  EdgeIndex() = default;
  // Every edge of the network; of edges joining the same pair (an invalid network) the first.
  explicit EdgeIndex(const Network& network);
  // Records edge e joining a and b; returns the edge that already joined them, or e.
  int add(int a, int b, int e);
  // The edge joining a and b, or -1.
  int find(int a, int b) const;

 private:
  std::map<std::pair<int, int>, int> by_ends_;  // unordered vertex pair (smaller first) -> edge
};

// Every use of every edge by a face side, [edge] -> uses in face then side order (a valid network
// has at most two per edge; an invalid one may have more). Sides whose vertices no edge joins are
// left out.
std::vector<std::vector<EdgeUse>> edge_uses(const Network& network, const EdgeIndex& index);

// Checks the rules of scene-format.md (vertex indices, loops, one edge per consecutive pair,
// shared edges traversed in opposite directions, at most two faces per edge). Throws DataError
// with source and the JSON path of the offending item ("network.faces[3].loop[2]").
NetworkTopology validate_network(const Network& network, const std::string& source);

// Interior control of GB faces. A face of degree d has l = ceil(d/2) layers per ribbon (the
// .gbp layer count); layers 0 and 1 are G1 data, so point [i, j, k] is free when it lies in a
// layer k >= 2 at least two points from either end of its row (min(k, j, d - j) >= 2: the
// corner-block positions outside that range are points of a lower layer of the neighbouring
// ribbon).
inline constexpr int kMaxGBFaceDegree = 15;
inline int gb_face_layers(int degree) {
  return (degree + 1) / 2;
}
bool is_free_interior_point(int degree, const InteriorOffset& at);
// Why offset `at` cannot be applied to a face of n sides and degree d, or "" if it can.
std::string interior_offset_problem(int sides, int degree, const InteriorOffset& at);

// The scheme a face is filled with: Auto resolves to Gregory for 3 and 4 sides, GB otherwise;
// an override (from --scheme) applies where the face allows it.
FaceScheme resolve_scheme(const NetworkFace& face, std::optional<FaceScheme> override_scheme);

}  // namespace pl
