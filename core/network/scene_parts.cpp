#include "core/network/scene_parts.hpp"

#include "core/scene/surface_names.hpp"

namespace pl {

SceneParts scene_parts(const Scene& scene, std::optional<FaceScheme> scheme,
                       const std::string& source) {
  SceneParts parts;
  if (scene.network) {
    parts.topology = validate_network(*scene.network, source);
    parts.filling = fill_network(*scene.network, *parts.topology, scheme, source);
    for (const FacePatch& fp : parts.filling.faces)
      parts.face_names.push_back(face_surface_name(*scene.network, fp.face));
  }
  for (std::size_t i = 0; i < scene.patches.size(); ++i)
    parts.patch_names.push_back(patch_surface_name(scene, i));
  return parts;
}

}  // namespace pl
