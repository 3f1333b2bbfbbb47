// The camera JSON file of `patchlab render --view FILE`:
//   {"target": [x, y, z], "yaw_deg": -45, "pitch_deg": 35, "distance": 4,
//    "fov_deg": 30, "projection": "perspective" | "orthographic"}
// or {"eye": [x, y, z], "target": [x, y, z], ...}. Every key is optional; a missing target or
// distance is taken from framing the scene, missing angles from the iso view.
#pragma once

#include <filesystem>

#include "render/camera.hpp"

namespace pl {

// Throws DataError naming the file and the JSON path.
Camera read_camera_file(const std::filesystem::path& path, const Box& scene_box, double aspect);

}  // namespace pl
