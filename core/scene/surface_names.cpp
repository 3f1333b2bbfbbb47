#include "core/scene/surface_names.hpp"

namespace pl {

std::string face_surface_name(const Network& network, int face) {
  const std::string& name = network.faces.at(face).name;
  return name.empty() ? "face" + std::to_string(face) : name;
}

std::string patch_surface_name(const Scene& scene, std::size_t patch) {
  const std::string& name = scene.patches.at(patch).name;
  return name.empty() ? "patch" + std::to_string(patch) : name;
}

std::string piece_name(const std::string& owner, std::size_t pieces, std::size_t k) {
  return pieces == 1 ? owner : owner + "." + std::to_string(k);
}

}  // namespace pl
