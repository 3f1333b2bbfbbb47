// The walk over a scene's surfaces that evaluation and CAD export share, in the order every output
// lists them: the network's faces (checked and filled) in network order, then the explicit
// patches in scene order, each under its surface name (core/scene/surface_names.hpp).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/network/network_filling.hpp"
#include "core/scene/scene.hpp"

namespace pl {

struct SceneParts {
  std::optional<NetworkTopology> topology;  // when the scene has a network
  NetworkFilling filling;                   // its faces, in network order
  std::vector<std::string> face_names;      // parallel to filling.faces
  std::vector<std::string> patch_names;     // parallel to scene.patches
};

// Throws DataError (naming `source`) for a network it cannot check or fill.
SceneParts scene_parts(const Scene& scene, std::optional<FaceScheme> scheme,
                       const std::string& source);

}  // namespace pl
