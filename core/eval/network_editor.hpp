// Interactive editing of a curve network: moving a vertex or an edge handle recomputes only what
// depends on it (the tangent plane at the vertex, the Chiyokura–Kimura fields of the edges at
// that vertex, the patches of the faces using those edges) and updates those faces' samples
// incrementally, the changed control points of a face moved together
// (PatchEvaluator::move_control_points).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/domain/tessellation_cache.hpp"
#include "core/eval/patch_evaluator.hpp"
#include "core/network/chiyokura_kimura.hpp"
#include "core/network/network_filling.hpp"
#include "core/network/tangent_planes.hpp"

namespace pl {

class NetworkEditor {
 public:
  // Validates and fills the network like fill_network (same DataErrors). density >= 1.
  NetworkEditor(Network network, std::optional<FaceScheme> scheme, int density,
                TessellationCache& cache, std::string source = "");

  const Network& network() const { return network_; }
  const NetworkTopology& topology() const { return topology_; }
  int face_count() const { return static_cast<int>(evaluators_.size()); }
  const PatchEvaluator& evaluator(int face) const { return *evaluators_.at(face); }
  const std::vector<int>& patch_side(int face) const { return patch_side_.at(face); }
  std::vector<ProjectedVertex> projected() const { return projected_vertices(planes_); }

  struct Update {
    std::vector<int> faces;        // faces whose patch changed, ascending
    std::size_t moved_points = 0;  // control points moved in their evaluators
  };
  // Moves vertex v to p. The handles next to v move with it, so its end tangents keep their
  // direction and length (what a designer dragging a vertex expects).
  Update move_vertex(int v, const Vec3& p);
  // Moves handle k (0: next to edges[e].v[0], 1: next to v[1]) of edge e to p.
  Update move_handle(int e, int k, const Vec3& p);

 private:
  // Recomputes the planes at `vertices`, the fields of their edges and the faces using those
  // edges. On a DataError the derived data is restored; the caller restores the network.
  Update refresh(const std::vector<int>& vertices);

  Network network_;
  NetworkTopology topology_;
  std::string source_;
  std::vector<FaceScheme> schemes_;
  std::vector<TangentPlane> planes_;
  std::vector<EdgeCrossTangents> cross_;
  std::vector<std::shared_ptr<const Tessellation>> tessellations_;
  std::vector<std::unique_ptr<PatchEvaluator>> evaluators_;
  std::vector<std::vector<int>> patch_side_;
};

}  // namespace pl
