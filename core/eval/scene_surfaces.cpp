#include "core/eval/scene_surfaces.hpp"

#include <map>

namespace pl {

SceneSurfaces evaluate_scene(const Scene& scene, int density, std::optional<FaceScheme> scheme,
                             TessellationCache& cache, const std::string& source) {
  SceneSurfaces out;
  std::map<int, int> surface_of_face;
  if (scene.network) {
    const NetworkTopology topo = validate_network(*scene.network, source);
    NetworkFilling filling = fill_network(*scene.network, topo, scheme, source);
    out.projected_vertices = std::move(filling.projected_vertices);
    for (FacePatch& fp : filling.faces) {
      SceneSurface s;
      const auto& face = scene.network->faces[fp.face];
      s.name = face.name.empty() ? "face" + std::to_string(fp.face) : face.name;
      s.face = fp.face;
      s.patch_side = fp.patch_side;
      auto tess = cache.get(fp.patch->domain(), density);
      s.evaluator = std::make_unique<PatchEvaluator>(std::move(fp.patch), std::move(tess));
      surface_of_face[fp.face] = static_cast<int>(out.surfaces.size());
      out.surfaces.push_back(std::move(s));
    }
    for (std::size_t e = 0; e < topo.edge_faces.size(); ++e) {
      const auto& uses = topo.edge_faces[e];
      if (uses.size() != 2) continue;
      SharedEdge se;
      se.edge = static_cast<int>(e);
      for (int k = 0; k < 2; ++k) {
        const int s = surface_of_face.at(uses[k].face);
        se.surface[k] = s;
        se.side[k] = out.surfaces[s].patch_side.at(uses[k].side);
      }
      out.shared_edges.push_back(se);
    }
  }
  for (std::size_t i = 0; i < scene.patches.size(); ++i) {
    const ScenePatch& sp = scene.patches[i];
    const std::string name = sp.name.empty() ? "patch" + std::to_string(i) : sp.name;
    const auto pieces = surface_pieces_of(*sp.patch);
    for (std::size_t k = 0; k < pieces.size(); ++k) {
      SceneSurface s;
      s.name = pieces.size() == 1 ? name : name + "." + std::to_string(k);
      s.patch = static_cast<int>(i);
      auto tess = cache.get(pieces[k]->domain(), density);
      s.evaluator = std::make_unique<PatchEvaluator>(pieces[k], std::move(tess));
      out.surfaces.push_back(std::move(s));
    }
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
