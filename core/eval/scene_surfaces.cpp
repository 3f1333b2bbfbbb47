#include "core/eval/scene_surfaces.hpp"

#include <optional>

#include "core/base/parallel_for.hpp"
#include "core/network/scene_parts.hpp"
#include "core/patch/gb/shared_basis.hpp"
#include "core/scene/surface_names.hpp"

namespace pl {

SceneSurfaces evaluate_scene(const Scene& scene, int density, std::optional<FaceScheme> scheme,
                             TessellationCache& cache, const std::string& source,
                             const std::shared_ptr<SampleBufferPool>& pool) {
  SceneSurfaces out;
  SceneParts parts = scene_parts(scene, scheme, source);
  if (parts.topology) {
    NetworkFilling& filling = parts.filling;
    out.projected_vertices = std::move(filling.projected_vertices);
    // Faces evaluated side by side over the cores (each evaluation also splits its samples): a
    // network of many small faces is not a queue of small parallel loops.
    out.surfaces.resize(filling.faces.size());
    const bool alone = shared_basis_bypassed();  // the caller's, for every face's thread
    parallel_each(filling.faces.size(), 1, [&](std::size_t i) {
      std::optional<SharedBasisBypass> own;
      if (alone) own.emplace();
      FacePatch& fp = filling.faces[i];
      SceneSurface& s = out.surfaces[i];
      s.name = std::move(parts.face_names[i]);
      s.face = fp.face;
      s.patch_side = fp.patch_side;
      auto tess = cache.get(fp.patch->domain(), density);
      s.evaluator = std::make_unique<PatchEvaluator>(std::move(fp.patch), std::move(tess),
                                                     SampleStorage::Jets, pool);
    });
    out.shared_edges = shared_edges_of(*parts.topology, out.surfaces);
  }
  for (std::size_t i = 0; i < scene.patches.size(); ++i) {
    const ScenePatch& sp = scene.patches[i];
    const auto pieces = surface_pieces_of(*sp.patch);
    for (std::size_t k = 0; k < pieces.size(); ++k) {
      SceneSurface s;
      s.name = piece_name(parts.patch_names[i], pieces.size(), k);
      s.patch = static_cast<int>(i);
      auto tess = cache.get(pieces[k]->domain(), density);
      s.evaluator =
          std::make_unique<PatchEvaluator>(pieces[k], std::move(tess), SampleStorage::Jets, pool);
      out.surfaces.push_back(std::move(s));
    }
  }
  return out;
}

std::vector<SharedEdge> shared_edges_of(const NetworkTopology& topo,
                                        const std::vector<SceneSurface>& surfaces) {
  std::vector<SharedEdge> out;
  for (std::size_t e = 0; e < topo.edge_faces.size(); ++e) {
    const auto& uses = topo.edge_faces[e];
    if (uses.size() != 2) continue;
    SharedEdge se;
    se.edge = static_cast<int>(e);
    for (int k = 0; k < 2; ++k) {
      se.surface[k] = uses[k].face;  // face f is surface f
      se.side[k] = surfaces.at(uses[k].face).patch_side.at(uses[k].side);
    }
    out.push_back(se);
  }
  return out;
}

std::vector<std::shared_ptr<Patch>> surface_pieces_of(const Patch& patch) {
  auto pieces = patch.surface_pieces();
  // Evaluators move control points, so each gets its own copy of the scene's patch.
  if (pieces.empty()) pieces.push_back(patch.clone());
  return pieces;
}

}  // namespace pl
