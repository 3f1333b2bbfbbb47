// Every surface of a scene, evaluated at one density: explicit patches and filled network faces,
// with the shared edges between network faces for continuity analysis.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/domain/tessellation_cache.hpp"
#include "core/eval/patch_evaluator.hpp"
#include "core/network/network_filling.hpp"
#include "core/scene/scene.hpp"

namespace pl {

struct SceneSurface {
  std::string name;             // the face's or patch's name, or face<i> / patch<i>
  int face = -1;                // network face index, or -1 for an explicit patch
  int patch = -1;               // index into Scene::patches for explicit patches (several
                                // surfaces share one when it has surface_pieces()), else -1
  std::vector<int> patch_side;  // for faces: face side -> patch domain side
  std::unique_ptr<PatchEvaluator> evaluator;
};

struct SharedEdge {
  int edge = -1;
  int surface[2] = {-1, -1};  // indices into SceneSurfaces::surfaces
  int side[2] = {-1, -1};     // patch domain sides; side 1 runs opposite to side 0
};

struct SceneSurfaces {
  std::vector<SceneSurface> surfaces;
  std::vector<SharedEdge> shared_edges;
  std::vector<ProjectedVertex> projected_vertices;
};

// The edges two faces share, for surfaces that list network face f as surface f.
std::vector<SharedEdge> shared_edges_of(const NetworkTopology& topology,
                                        const std::vector<SceneSurface>& surfaces);

// The surfaces a scene patch is drawn as: its surface_pieces(), or the patch itself.
std::vector<std::shared_ptr<Patch>> surface_pieces_of(const Patch& patch);

// Throws DataError for data it cannot evaluate. density >= 1. With a pool, the evaluators take
// their sample storage from it and give it back when they go (core/eval/sample_buffer_pool.hpp).
SceneSurfaces evaluate_scene(const Scene& scene, int density, std::optional<FaceScheme> scheme,
                             TessellationCache& cache, const std::string& source,
                             const std::shared_ptr<SampleBufferPool>& pool = nullptr);

}  // namespace pl
